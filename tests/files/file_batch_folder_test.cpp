// A folder of an output (a case's trajectories) switches in whole with the batch, with a
// record of its own; it replaces or leaves an earlier folder of that name only when that
// one holds nothing but what its own record lists.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "files/file_batch.hpp"
#include "files/folder_manifest.hpp"
#include "support/program.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

/// An output folder holding an earlier `c-steps` folder with a.csv and b.csv, both in its
/// own record, and the folder in the output folder's record.
std::string output_with_folder(const std::string& name) {
  const std::string out = test::fresh_dir(name);
  fs::create_directories(out + "/c-steps");
  std::ofstream(out + "/c-steps/a.csv") << "old a";
  std::ofstream(out + "/c-steps/b.csv") << "old b";
  std::ofstream(out + "/c-steps/" + kManifestName) << manifest_text({"a.csv", "b.csv"});
  std::ofstream(out + "/" + kManifestName) << manifest_text({"c-steps"});
  return out;
}

TEST(FileBatchFolder, AFolderIsPutWholeWithItsOwnRecordReplacingTheEarlierOne) {
  const std::string out = output_with_folder("batch_folder_put");
  {
    FileBatch batch(out);
    const std::string steps = batch.folder_for("c-steps");
    // Written by anyone (a run's child process) into the folder the batch gave.
    std::ofstream(steps + "/a.csv") << "new a";
    batch.write("c.json", "json");
    EXPECT_FALSE(fs::exists(out + "/c.json")) << "switched in before commit";
    batch.commit();
  }
  EXPECT_EQ(test::bytes(out + "/c-steps/a.csv"), "new a");
  EXPECT_FALSE(fs::exists(out + "/c-steps/b.csv")) << "a file of the earlier folder stayed";
  EXPECT_EQ(read_manifest(out + "/c-steps"), std::set<std::string>{"a.csv"});
  EXPECT_EQ(read_manifest(out), (std::set<std::string>{"c-steps", "c.json"}));
  EXPECT_TRUE(holds_only_recorded_files(out + "/c-steps"));
  EXPECT_EQ(test::temporaries_in(out), "");
}

TEST(FileBatchFolder, ARecordedFolderDroppedGoesWhole) {
  const std::string out = output_with_folder("batch_folder_drop");
  FileBatch batch(out);
  batch.drop("c-steps");
  batch.commit();
  EXPECT_FALSE(fs::exists(out + "/c-steps"));
  EXPECT_TRUE(read_manifest(out).empty());
}

TEST(FileBatchFolder, AFolderHoldingAFileItsRecordDoesNotListIsNeitherReplacedNorDropped) {
  const std::string out = output_with_folder("batch_folder_foreign");
  std::ofstream(out + "/c-steps/notes.txt") << "the user's";
  const auto before = test::snapshot(out);
  std::string foreign;
  EXPECT_FALSE(holds_only_recorded_files(out + "/c-steps", &foreign));
  EXPECT_EQ(foreign, "notes.txt");
  for (const bool put : {true, false}) {
    FileBatch batch(out);
    if (put)
      std::ofstream(batch.folder_for("c-steps") + "/a.csv") << "new a";
    else
      batch.drop("c-steps");
    try {
      batch.commit();
      ADD_FAILURE() << "the folder was switched with the user's file in it";
    } catch (const WriteError& e) {
      EXPECT_NE(std::string(e.what()).find("c-steps/notes.txt"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(test::snapshot(out), before);
}

TEST(FileBatchFolder, AFolderTheOutputsRecordDoesNotListIsNotReplaced) {
  const std::string out = output_with_folder("batch_folder_unlisted");
  std::ofstream(out + "/" + kManifestName) << manifest_text({});
  const auto before = test::snapshot(out);
  {
    FileBatch batch(out);
    std::ofstream(batch.folder_for("c-steps") + "/a.csv") << "new a";
    EXPECT_THROW(batch.commit(), WriteError);
  }
  EXPECT_EQ(test::snapshot(out), before);
}

}  // namespace
}  // namespace bb
