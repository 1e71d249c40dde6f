// Whole-file reads and atomic saves: errors name the path and the reason, and a failed save leaves neither a
// damaged target nor a temporary file behind. Tests run as root, so "unwritable" is made with paths the kernel
// refuses for everyone (a directory under a regular file, a directory as the target), not with chmod.
#include "vox/io/file_util.h"

#include <gtest/gtest.h>

#include "support/test_support.h"

namespace vox::io {
namespace {

size_t entriesIn(const std::filesystem::path& dir) {
  size_t n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++n;
  return n;
}

TEST(FileUtil, writeThenReadGivesTheSameBytes) {
  test::TempDir tmp;
  std::vector<uint8_t> bytes(300000);
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = uint8_t(i * 7 + 3);
  ASSERT_TRUE(writeFileAtomic(tmp / "a.bin", bytes).ok());
  const auto r = readFileBytes(tmp / "a.bin");
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r.value(), bytes);
  EXPECT_EQ(entriesIn(tmp.path()), 1u);  // no temporary file left
}

TEST(FileUtil, emptyFileReadsAsNoBytes) {
  test::TempDir tmp;
  ASSERT_TRUE(writeFileAtomic(tmp / "e", std::string()).ok());
  const auto r = readFileBytes(tmp / "e");
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_TRUE(r->empty());
}

TEST(FileUtil, saveReplacesAnExistingFileAndKeepsItsMode) {
  test::TempDir tmp;
  test::writeFile(tmp / "a.txt", "old contents");
  std::filesystem::permissions(tmp / "a.txt", std::filesystem::perms(0640));
  ASSERT_TRUE(writeFileAtomic(tmp / "a.txt", std::string("new")).ok());
  EXPECT_EQ(test::readFile(tmp / "a.txt"), "new");
  EXPECT_EQ(std::filesystem::status(tmp / "a.txt").permissions(), std::filesystem::perms(0640));
}

TEST(FileUtil, readingAMissingFileNamesPathAndReason) {
  test::TempDir tmp;
  const auto r = readFileBytes(tmp / "missing.stl");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, ErrorCode::kIo);
  EXPECT_EQ(r.error().message, (tmp / "missing.stl").string() + ": cannot open: No such file or directory");
}

TEST(FileUtil, readingADirectoryIsRefused) {
  test::TempDir tmp;
  const auto r = readFileBytes(tmp.path());
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message, tmp.path().string() + ": is a directory, not a file");
}

TEST(FileUtil, savingUnderARegularFileFailsWithNotADirectory) {
  test::TempDir tmp;
  test::writeFile(tmp / "plain", "x");
  const auto target = tmp / "plain" / "out.vxm";
  const Status s = writeFileAtomic(target, std::string("data"));
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().code, ErrorCode::kIo);
  EXPECT_EQ(s.error().message, target.string() + ": cannot create a temporary file in '" + (tmp / "plain").string() +
                                   "': Not a directory");
  EXPECT_EQ(test::readFile(tmp / "plain"), "x");
}

TEST(FileUtil, savingIntoAMissingDirectoryFails) {
  test::TempDir tmp;
  const auto target = tmp / "no" / "such" / "dir" / "out.png";
  const Status s = writeFileAtomic(target, std::string("data"));
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().message.find(target.string() + ": "), std::string::npos);
  EXPECT_NE(s.error().message.find("No such file or directory"), std::string::npos) << s.error().message;
  EXPECT_EQ(entriesIn(tmp.path()), 0u);
}

TEST(FileUtil, savingIntoProcFailsAndSaysWhy) {
  const Status s = writeFileAtomic("/proc/voxmod-test.vxm", std::string("data"));
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().code, ErrorCode::kIo);
  EXPECT_EQ(s.error().message.rfind("/proc/voxmod-test.vxm: cannot create a temporary file in '/proc': ", 0), 0u)
      << s.error().message;
}

TEST(FileUtil, failedRenameRemovesTheTemporaryFileAndLeavesTheTargetAlone) {
  // The temporary file is created and written, then rename() refuses to replace a non-empty directory: the
  // failure happens after the temporary file exists, so this checks the clean-up.
  test::TempDir tmp;
  std::filesystem::create_directory(tmp / "out.vxm");
  test::writeFile(tmp / "out.vxm" / "inside", "keep");
  const Status s = writeFileAtomic(tmp / "out.vxm", std::string("data"));
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().code, ErrorCode::kIo);
  EXPECT_EQ(s.error().message, (tmp / "out.vxm").string() + ": cannot replace the file: Is a directory");
  EXPECT_EQ(test::readFile(tmp / "out.vxm" / "inside"), "keep");
  EXPECT_EQ(entriesIn(tmp.path()), 1u);  // only the directory: no temporary file left
}

TEST(FileUtil, longFileNameSaves) {
  // 250 characters fit NAME_MAX (255); the temporary name derived from it must fit too.
  test::TempDir tmp;
  const std::string long_name(250, 'n');
  ASSERT_TRUE(writeFileAtomic(tmp / long_name, std::string("data")).ok());
  EXPECT_EQ(test::readFile(tmp / long_name), "data");
  EXPECT_EQ(entriesIn(tmp.path()), 1u);
}

}  // namespace
}  // namespace vox::io
