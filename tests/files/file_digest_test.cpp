// A file's digest is the digest of its bytes whatever its length falls on (empty, inside one
// 32-byte block of the hash, across the reads' blocks); one byte changed anywhere changes it; a
// file rewritten in place is read again; a file that cannot be read has no digest.
#include "files/file_digest.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

#include "support/program.hpp"

namespace bb {
namespace {

std::string random_bytes(std::size_t n, unsigned seed) {
  std::mt19937 draw(seed);
  std::string bytes(n, '\0');
  for (char& c : bytes) c = static_cast<char>(draw() & 0xff);
  return bytes;
}

/// An empty folder of the test's own.
std::string empty_folder(const std::string& name) {
  const std::string folder = test::fresh_dir(name);
  std::filesystem::create_directories(folder);
  return folder;
}

void put_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

TEST(FileDigest, IsTheDigestOfTheFilesBytesAtEveryLengthAroundItsBlocks) {
  const std::string folder = empty_folder("file_digest_lengths");
  // Lengths at the hash's 32-byte blocks and around the reads' blocks (64 KiB and more).
  for (const std::size_t n : {0, 1, 31, 32, 33, 65535, 65536, 65537, 200003, 1 << 21}) {
    const std::string path = folder + "/f" + std::to_string(n);
    const std::string bytes = random_bytes(n, static_cast<unsigned>(n));
    put_bytes(path, bytes);
    const std::string d = file_digest(path);
    EXPECT_EQ(d.size(), 32u) << n;
    EXPECT_EQ(d, bytes_digest(bytes)) << n << " bytes";
  }
}

TEST(FileDigest, OneByteChangedAnywhereChangesIt) {
  const std::string folder = empty_folder("file_digest_one_byte");
  const std::string bytes = random_bytes(150000, 7);
  put_bytes(folder + "/original", bytes);
  const std::string original = file_digest(folder + "/original");
  for (const std::size_t at : {std::size_t{0}, std::size_t{65536}, bytes.size() - 1}) {
    std::string changed = bytes;
    changed[at] = static_cast<char>(changed[at] ^ 1);
    const std::string path = folder + "/changed" + std::to_string(at);
    put_bytes(path, changed);
    EXPECT_NE(file_digest(path), original) << "byte " << at;
  }
}

TEST(FileDigest, AFileRewrittenInPlaceIsReadAgainAndAMissingOneHasNone) {
  const std::string path = empty_folder("file_digest_rewritten") + "/f";
  put_bytes(path, "first version");
  EXPECT_EQ(file_digest(path), bytes_digest("first version"));
  put_bytes(path, "the second version, longer");
  EXPECT_EQ(file_digest(path), bytes_digest("the second version, longer"));
  EXPECT_EQ(file_digest(path + ".missing"), "");
}

}  // namespace
}  // namespace bb
