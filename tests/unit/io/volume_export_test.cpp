// Volume export by extension (volume_export.h): the format each extension picks, what each format holds, and
// atomic writes: a failure (an unwritable directory, a full disk) leaves nothing behind and names the file.
#include <sys/mount.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "support/grids.h"
#include "support/test_support.h"
#include "vox/io/file_util.h"
#include "vox/io/nrrd.h"
#include "vox/io/volume_export.h"

namespace vox::io {
namespace {

int entries(const std::filesystem::path& dir) {
  int n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++n;
  return n;
}

TEST(VolumeExport, theExtensionPicksTheFormatInAnyCase) {
  EXPECT_EQ(volumeFormatOf("a/part.nrrd"), VolumeFormat::kNrrd);
  EXPECT_EQ(volumeFormatOf("part.VTI"), VolumeFormat::kVti);
  EXPECT_EQ(volumeFormatOf("part.vdb"), VolumeFormat::kVdb);
  EXPECT_EQ(volumeFormatOf("part.Vox"), VolumeFormat::kVox);
  EXPECT_FALSE(isVolumeFile("part.vxm"));
  EXPECT_FALSE(isVolumeFile("part.stl"));
  EXPECT_FALSE(isVolumeFile("vti"));
  EXPECT_EQ(volumeExtensionList(), ".nrrd, .vti, .vdb or .vox");
  EXPECT_EQ(volumeExtensionList(true), ".nrrd, .vti or .vdb");
}

TEST(VolumeExport, eachFormatHoldsWhatItCan) {
  VoxelGrid g(Dims{4, 4, 4});
  ScalarField a(g.dims(), g.frame()), b(g.dims(), g.frame());
  const VolumeContent both{&g, {{"thickness", &a}}};
  const VolumeContent two_fields{nullptr, {{"thickness", &a}, {"distance", &b}}};
  EXPECT_EQ(volumeContentProblem(voxelsOnly(g), VolumeFormat::kVox), "");
  EXPECT_NE(volumeContentProblem(oneField("thickness", a), VolumeFormat::kVox).find("voxels only"), std::string::npos);
  EXPECT_EQ(volumeContentProblem(oneField("thickness", a), VolumeFormat::kNrrd), "");
  EXPECT_NE(volumeContentProblem(both, VolumeFormat::kNrrd).find("one volume per file"), std::string::npos);
  EXPECT_EQ(volumeContentProblem(both, VolumeFormat::kVti), "");
  EXPECT_EQ(volumeContentProblem(two_fields, VolumeFormat::kVdb), "");
  const VolumeContent dup{&g, {{"voxels", &a}}};
  EXPECT_NE(volumeContentProblem(dup, VolumeFormat::kVti).find("two volumes are named 'voxels'"), std::string::npos);
  EXPECT_EQ(volumeContentProblem(VolumeContent{}, VolumeFormat::kVti), "nothing to write");
}

TEST(VolumeExport, nrrdThroughTheDispatcherIsTheNrrdWriterWithItsUnits) {
  test::TempDir dir;
  VoxelGrid g = test::randomGrid(Dims{5, 4, 3}, 0.5, 2);
  g.frame().units = "mm";
  ASSERT_TRUE(saveVolume(voxelsOnly(g), dir / "g.nrrd").ok());
  auto direct = encodeNrrd(g);
  ASSERT_TRUE(direct.ok());
  EXPECT_EQ(test::readFile(dir / "g.nrrd"), std::string(direct->begin(), direct->end()));
  EXPECT_NE(test::readFile(dir / "g.nrrd").find("space units: \"mm\" \"mm\" \"mm\""), std::string::npos);
  auto back = loadNrrdField(dir / "g.nrrd");
  ASSERT_TRUE(back.ok()) << back.error().message;
  EXPECT_EQ(back->frame.units, "mm");
}

TEST(VolumeExport, anUnknownExtensionOrUnfitContentIsAnErrorNamingTheFile) {
  test::TempDir dir;
  VoxelGrid g(Dims{2, 2, 2});
  auto s = saveVolume(voxelsOnly(g), dir / "part.raw");
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().message.find("part.raw"), std::string::npos);
  EXPECT_NE(s.error().message.find(".nrrd, .vti, .vdb or .vox"), std::string::npos) << s.error().message;
  ScalarField f(g.dims(), g.frame());
  s = saveVolume(oneField("thickness", f), dir / "t.vox");
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().message.find("t.vox"), std::string::npos);
  EXPECT_EQ(entries(dir.path()), 0);
}

// Every format into a directory that cannot be written: an error naming the file, and nothing left there.
TEST(VolumeExport, aDirectoryThatCannotBeWrittenIsLeftEmpty) {
  test::TempDir tmp;
  const auto dir = tmp / "locked";
  std::filesystem::create_directory(dir);
  // Root writes anywhere a mode allows nothing, so root locks the directory with a read-only mount instead.
  bool mounted = false;
  if (::geteuid() == 0) {
    mounted = ::mount("tmpfs", dir.c_str(), "tmpfs", MS_RDONLY, "size=64k") == 0;
    if (!mounted) GTEST_SKIP() << "cannot mount a read-only tmpfs: " << std::strerror(errno);
  } else {
    ASSERT_EQ(::chmod(dir.c_str(), 0555), 0);
  }
  VoxelGrid g = test::randomGrid(Dims{20, 20, 20}, 0.5, 4);
  for (const char* name : {"part.nrrd", "part.vti", "part.vdb", "part.vox"}) {
    SCOPED_TRACE(name);
    const Status s = saveVolume(voxelsOnly(g), dir / name);
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().code, ErrorCode::kIo);
    EXPECT_NE(s.error().message.find((dir / name).string()), std::string::npos) << s.error().message;
  }
  EXPECT_EQ(entries(dir), 0);
  if (mounted) ::umount(dir.c_str());
  ::chmod(dir.c_str(), 0755);
}

// Every format onto a 64 KiB file system: "No space left on device", the previous file intact, no temporary left.
TEST(VolumeExport, aFullDiskKeepsThePreviousFileAndLeavesNoTemporary) {
  test::TempDir tmp;
  const auto dir = tmp / "small";
  std::filesystem::create_directory(dir);
  if (::mount("tmpfs", dir.c_str(), "tmpfs", 0, "size=64k") != 0) {
    GTEST_SKIP() << "cannot mount a small tmpfs to fill (needs root): " << std::strerror(errno);
  }
  VoxelGrid noisy = test::randomGrid(Dims{200, 200, 60}, 0.5, 8);  // compresses badly: megabytes in every format
  for (const char* name : {"part.nrrd", "part.vti", "part.vdb", "part.vox"}) {
    SCOPED_TRACE(name);
    ASSERT_TRUE(writeFileAtomic(dir / name, std::string("previous")).ok());
    const Status s = saveVolume(voxelsOnly(noisy), dir / name);
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().message.find((dir / name).string()), std::string::npos) << s.error().message;
    EXPECT_NE(s.error().message.find("No space left on device"), std::string::npos) << s.error().message;
    EXPECT_EQ(test::readFile(dir / name), "previous");
    std::filesystem::remove(dir / name);
    EXPECT_EQ(entries(dir), 0) << "a temporary file was left";
  }
  ::umount(dir.c_str());
}

}  // namespace
}  // namespace vox::io
