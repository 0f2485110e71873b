// A case's files switch in as one unit: a move that fails puts every file back, a switch
// cut short by a kill is finished by the next writer, and only files the folder's record
// lists are ever moved aside or removed.
#include "files/file_batch.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "files/folder_manifest.hpp"
#include "support/program.hpp"
#include "support/temporaries.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

/// A folder holding an earlier output: a.json and a.md, both in its record.
std::string earlier_output(const std::string& name) {
  const std::string folder = test::fresh_dir(name);
  fs::create_directories(folder);
  std::ofstream(folder + "/a.json") << "old json";
  std::ofstream(folder + "/a.md") << "old md";
  std::ofstream(folder + "/" + kManifestName) << manifest_text({"a.json", "a.md"});
  return folder;
}

TEST(FileBatch, ACommitReplacesTheSetAndRecordsIt) {
  const std::string folder = earlier_output("batch_commit");
  std::ofstream(folder + "/notes.txt") << "the user's";
  {
    FileBatch batch(folder);
    batch.write("a.json", "new json");
    batch.write("a.csv", "new csv");
    batch.drop("a.md");
    batch.drop("notes.txt");  // not in the record: never removed
    batch.commit();
  }
  EXPECT_EQ(test::bytes(folder + "/a.json"), "new json");
  EXPECT_EQ(test::bytes(folder + "/a.csv"), "new csv");
  EXPECT_FALSE(fs::exists(folder + "/a.md"));
  EXPECT_EQ(test::bytes(folder + "/notes.txt"), "the user's");
  EXPECT_EQ(read_manifest(folder), (std::set<std::string>{"a.csv", "a.json"}));
  EXPECT_EQ(test::temporaries_in(folder), "");
}

TEST(FileBatch, AMoveThatFailsPutsEveryFileBack) {
  const std::string folder = earlier_output("batch_rollback");
  const auto before = test::snapshot(folder);
  {
    FileBatch batch(folder);
    batch.write("a.json", "new json");
    // The second file's move fails after the first succeeded: it vanished from the batch.
    const std::string md = batch.path_for("a.md");
    std::ofstream(md) << "new md";
    fs::remove(md);
    EXPECT_THROW(batch.commit(), WriteError);
  }
  EXPECT_EQ(test::snapshot(folder), before) << "a half-switched set";
  EXPECT_EQ(test::temporaries_in(folder), "");
}

TEST(FileBatch, AFileTheRecordDoesNotListStopsTheSwitchBeforeItStarts) {
  const std::string folder = earlier_output("batch_foreign");
  std::ofstream(folder + "/a.csv") << "the user's csv";
  const auto before = test::snapshot(folder);
  {
    FileBatch batch(folder);
    batch.write("a.json", "new json");
    batch.write("a.csv", "new csv");
    try {
      batch.commit();
      ADD_FAILURE() << "the user's a.csv was replaced";
    } catch (const WriteError& e) {
      EXPECT_NE(std::string(e.what()).find("a.csv"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(test::snapshot(folder), before);
}

TEST(FileBatch, ASwitchCutShortByAKillIsFinishedByTheNextWriter) {
  const std::string folder = earlier_output("batch_killed");
  // What a batch killed between its first and second move leaves: a.json moved in and its
  // old one aside, a.md and the record still waiting, the journal saying what to do.
  const std::string staging = test::abandoned_temporary(folder, kStagingPrefix);
  for (const char* part : {"/new", "/old", "/work"}) fs::create_directories(staging + part);
  fs::rename(folder + "/a.json", staging + "/old/a.json");
  std::ofstream(folder + "/a.json") << "new json";
  std::ofstream(staging + "/new/a.md") << "new md";
  std::ofstream(staging + "/new/" + kManifestName) << manifest_text({"a.json", "a.md"});
  std::ofstream(staging + "/switch.list") << "put a.json\nput a.md\nput " << kManifestName << "\n";
  EXPECT_EQ(finish_interrupted_switches(folder), 1);
  EXPECT_EQ(test::bytes(folder + "/a.json"), "new json");
  EXPECT_EQ(test::bytes(folder + "/a.md"), "new md");
  EXPECT_FALSE(fs::exists(staging));
}

TEST(FileBatch, ABatchKilledBeforeItsSwitchWasDecidedLeavesTheOldSet) {
  const std::string folder = earlier_output("batch_undecided");
  const auto before = test::snapshot(folder);
  const std::string staging = test::abandoned_temporary(folder, kStagingPrefix);
  fs::create_directories(staging + "/new");
  std::ofstream(staging + "/new/a.md") << "half written";
  EXPECT_EQ(finish_interrupted_switches(folder), 1);
  EXPECT_EQ(test::snapshot(folder), before);
}

TEST(OwnedTemporary, OnlyAnAbandonedFolderWithItsMarkerIsRemoved) {
  const std::string parent = test::fresh_dir("owned_temporaries");
  fs::create_directories(parent);
  const std::string dead = test::abandoned_temporary(parent, "beachball-scratch-");
  const OwnedTemporary living(parent, "beachball-scratch-");
  // Same shape of name, no marker: a user's folder.
  fs::create_directories(parent + "/beachball-scratch-0123456789abcdef");
  // A marker with other text: not beachball's.
  fs::create_directories(parent + "/beachball-scratch-forged");
  std::ofstream(parent + "/beachball-scratch-forged/" + kOwnerMarker) << "something else\n";
  EXPECT_EQ(remove_abandoned_temporaries(parent, "beachball-scratch-"), 1);
  EXPECT_FALSE(fs::exists(dead));
  EXPECT_TRUE(fs::exists(living.path()));
  EXPECT_TRUE(fs::exists(parent + "/beachball-scratch-0123456789abcdef"));
  EXPECT_TRUE(fs::exists(parent + "/beachball-scratch-forged"));
}

}  // namespace
}  // namespace bb
