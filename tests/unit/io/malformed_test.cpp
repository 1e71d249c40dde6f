// The checked-in corpus of broken files (tests/data/malformed/, written by tests/data/make_io_data.py): each
// reader (STL, .vxm, .binvox, and loadMeshFile's for the other mesh and CAD formats) refuses each file with the error
// code and the exact message asserted here. Valid files in unusual shapes
// (tests/data/quirks/) load.
#include <set>

#include <gtest/gtest.h>

#include "support/test_support.h"
#include "vox/io/mesh_file.h"
#include "vox/io/stl.h"
#include "vox/io/voxel_file.h"

namespace vox::io {
namespace {

std::filesystem::path dataDir() { return test::sourceDir() / "tests" / "data"; }

std::vector<uint8_t> bytesOf(const std::filesystem::path& p) {
  const std::string s = test::readFile(p);
  return {s.begin(), s.end()};
}

struct Refusal {
  const char* file;
  ErrorCode code;
  const char* message;  // the whole message; the file is named as it was given to the parser
};

// Decodes a file of the malformed corpus by its extension, naming it by its file name.
Error refusalOf(const std::string& file) {
  const std::vector<uint8_t> bytes = bytesOf(dataDir() / "malformed" / file);
  const std::string ext = std::filesystem::path(file).extension().string();
  if (ext == ".stl") {
    auto r = parseStl(bytes, file);
    return r.ok() ? Error{ErrorCode::kInvalidArgument, "<accepted>"} : r.error();
  }
  if (ext == ".vxm" || ext == ".binvox") {
    auto r = ext == ".vxm" ? decodeVxm(bytes, file) : decodeBinvox(bytes, file);
    return r.ok() ? Error{ErrorCode::kInvalidArgument, "<accepted>"} : r.error();
  }
  auto r = parseMeshFile(bytes, file);  // every other mesh and CAD format
  return r.ok() ? Error{ErrorCode::kInvalidArgument, "<accepted>"} : r.error();
}

const Refusal kRefusals[] = {
    // STL: binary size checks.
    {"empty.stl", ErrorCode::kParse, "empty.stl: file is empty"},
    {"too_short.stl", ErrorCode::kParse,
     "too_short.stl: not an STL file: 5 bytes is shorter than a binary STL header (84 bytes) and it does not "
     "start with 'solid'"},
    {"binary_truncated.stl", ErrorCode::kParse,
     "binary_truncated.stl: binary STL truncated: header declares 12 triangles (684 bytes) but the file has 334 "
     "bytes"},
    // STL: files of other kinds are named as not STL, not as a broken binary STL.
    {"not_stl_ply.stl", ErrorCode::kParse,
     "not_stl_ply.stl: not an STL file: it looks like a PLY file (name it .ply to read it as one)"},
    {"not_stl_text.stl", ErrorCode::kParse,
     "not_stl_text.stl: not an STL file: it is neither an ASCII STL (it does not start with 'solid') nor a binary "
     "STL (its size does not fit the triangle count at byte 80)"},
    {"binary_zero_triangles.stl", ErrorCode::kParse, "binary_zero_triangles.stl: binary STL contains no triangles"},
    {"binary_solid_header_truncated.stl", ErrorCode::kParse,
     "binary_solid_header_truncated.stl: binary STL truncated: header declares 4 triangles (284 bytes) but the "
     "file has 264 bytes (it starts with 'solid' but holds binary data, so it is not ASCII)"},
    // STL: binary coordinates.
    {"binary_nan.stl", ErrorCode::kParse,
     "binary_nan.stl: binary STL triangle 2 of 2 (byte offset 134) has a non-finite vertex coordinate (NaN or "
     "infinity)"},
    {"binary_inf.stl", ErrorCode::kParse,
     "binary_inf.stl: binary STL triangle 3 of 3 (byte offset 184) has a non-finite vertex coordinate (NaN or "
     "infinity)"},
    // STL: ASCII, with line numbers.
    {"ascii_nan.stl", ErrorCode::kParse, "ascii_nan.stl:5: vertex coordinate is not finite: 'nan'"},
    {"ascii_inf.stl", ErrorCode::kParse, "ascii_inf.stl:12: vertex coordinate is not finite: '-inf'"},
    {"ascii_out_of_range.stl", ErrorCode::kParse, "ascii_out_of_range.stl:5: number out of float32 range: '1e39'"},
    {"ascii_bad_token.stl", ErrorCode::kParse, "ascii_bad_token.stl:6: expected a number, found '1x'"},
    {"ascii_missing_endloop.stl", ErrorCode::kParse,
     "ascii_missing_endloop.stl:7: expected 'endloop', found 'endfacet'"},
    {"ascii_two_vertices.stl", ErrorCode::kParse, "ascii_two_vertices.stl:6: expected 'vertex', found 'endloop'"},
    {"ascii_truncated.stl", ErrorCode::kParse,
     "ascii_truncated.stl:12: the file ends early (truncated?): expected a number, found end of file"},
    {"ascii_cut_in_number.stl", ErrorCode::kParse,
     "ascii_cut_in_number.stl:11: the file ends early, in '-1.291420e' (truncated?): expected a number"},
    {"ascii_no_triangles.stl", ErrorCode::kParse, "ascii_no_triangles.stl: ASCII STL contains no triangles"},
    {"ascii_garbage_after_endsolid.stl", ErrorCode::kParse,
     "ascii_garbage_after_endsolid.stl:10: expected 'solid' or end of file, found 'facet'"},
    // .binvox
    {"binvox_truncated.binvox", ErrorCode::kParse,
     "binvox_truncated.binvox: binvox data is truncated: the runs cover 55 of 64 voxels"},
    {"binvox_odd_length.binvox", ErrorCode::kParse,
     "binvox_odd_length.binvox: binvox data is truncated: the runs cover 64 of 64 voxels and end with half a pair"},
    {"binvox_overrun.binvox", ErrorCode::kParse,
     "binvox_overrun.binvox: binvox data runs past the 64 voxels of the grid (at byte 58)"},
    {"binvox_bad_value.binvox", ErrorCode::kParse,
     "binvox_bad_value.binvox: binvox data has value 2 at byte 54 (values are 0 or 1)"},
    {"binvox_version2.binvox", ErrorCode::kUnsupported,
     "binvox_version2.binvox:1: binvox version 2 is not supported (this build reads version 1)"},
    {"binvox_no_data.binvox", ErrorCode::kParse, "binvox_no_data.binvox: binvox header has no 'data' line"},
    {"binvox_no_dim.binvox", ErrorCode::kParse, "binvox_no_dim.binvox: binvox header has no 'dim' line"},
    {"binvox_huge_dim.binvox", ErrorCode::kLimit, "binvox_huge_dim.binvox:2: dimension 20000 is outside 1..16384"},
    {"binvox_zero_run.binvox", ErrorCode::kParse,
     "binvox_zero_run.binvox: binvox data has a run of length 0 at byte 55 (run lengths are 1..255)"},
    // Bytes that are not text are quoted as '?', so the message (and the CLI's JSON) stays valid UTF-8.
    {"binvox_not_utf8_header.binvox", ErrorCode::kParse,
     "binvox_not_utf8_header.binvox:3: unknown binvox header line '??? data'"},
    {"binvox_not_binvox.binvox", ErrorCode::kParse,
     "binvox_not_binvox.binvox: not a binvox file (it does not start with '#binvox')"},
    // .vxm
    {"vxm_bad_magic.vxm", ErrorCode::kParse, "vxm_bad_magic.vxm: not a voxmod .vxm file (bad magic bytes)"},
    {"vxm_newer_version.vxm", ErrorCode::kUnsupported,
     "vxm_newer_version.vxm: written by a newer voxmod (format version 3; this build reads up to 1)"},
    {"vxm_truncated.vxm", ErrorCode::kParse,
     "vxm_truncated.vxm: .vxm file truncated: expected 110 bytes but the file has 107"},
    {"vxm_crc_mismatch.vxm", ErrorCode::kCorrupt,
     "vxm_crc_mismatch.vxm: .vxm file is corrupt: CRC-32 mismatch (stored ca1c5de9, computed d3076ca8)"},
    {"vxm_header_corrupt.vxm", ErrorCode::kCorrupt, "vxm_header_corrupt.vxm: .vxm header is corrupt (CRC-32 mismatch)"},
    {"vxm_runs_short.vxm", ErrorCode::kCorrupt,
     "vxm_runs_short.vxm: .vxm body is inconsistent: runs cover 11 of 12 voxels"},
    {"vxm_runs_long.vxm", ErrorCode::kCorrupt,
     "vxm_runs_long.vxm: .vxm body is inconsistent: runs cover more than the 12 voxels"},
    {"vxm_zero_run.vxm", ErrorCode::kCorrupt, "vxm_zero_run.vxm: .vxm body is inconsistent: empty run 3"},
    {"vxm_filled_mismatch.vxm", ErrorCode::kCorrupt,
     "vxm_filled_mismatch.vxm: .vxm body is inconsistent: header says 4 runs and 9 filled voxels, body has 4 and 7"},
    {"vxm_huge_dims.vxm", ErrorCode::kLimit, "<memory>"},
    {"vxm_dims_too_large.vxm", ErrorCode::kLimit,
     "vxm_dims_too_large.vxm: grid dimensions 20000 x 1 x 1 are outside 1..16384 per axis"},
    {"vxm_zero_voxel_size.vxm", ErrorCode::kCorrupt,
     "vxm_zero_voxel_size.vxm: .vxm header has a non-finite origin or a voxel size that is not positive"},
    // Mesh and CAD formats (loadMeshFile)
    {"empty.obj", ErrorCode::kParse, "empty.obj: file is empty"},
    {"obj_comments_only.obj", ErrorCode::kParse, "obj_comments_only.obj: OBJ file contains no triangles"},
    {"ply_lying_counts.ply", ErrorCode::kParse,
     "ply_lying_counts.ply:18: PLY vertex 9 of 9 has 5 values where the header declares 3: its counts do not match "
     "the data"},
    {"ply_binary_truncated.ply", ErrorCode::kParse,
     "ply_binary_truncated.ply: PLY data ends in face 6 of 6 (byte 181 of the body): the header declares more "
     "elements than the file holds"},
    {"ply_bad_index.ply", ErrorCode::kParse,
     "ply_bad_index.ply: not a readable PLY file (assimp: 'Validation failed: aiMesh::mFaces[5]::mIndices[3] is out "
     "of range')"},
    {"glb_then_zip.glb", ErrorCode::kParse,
     "glb_then_zip.glb: not a readable GLB file (assimp's GLB importers do not recognise its content)"},
    {"glb_chunk_too_long.glb", ErrorCode::kParse,
     "glb_chunk_too_long.glb: GLB chunk 1 says 4293918720 bytes where 708 remain"},
    {"gltf_truncated.gltf", ErrorCode::kParse,
     "gltf_truncated.gltf: not a readable glTF file (assimp's glTF importers do not recognise its content)"},
    {"gltf_bad_buffer_view.gltf", ErrorCode::kParse,
     "gltf_bad_buffer_view.gltf: not a readable glTF file (assimp: 'GLTF: Array index 7 is out of bounds (2) for "
     "\"bufferViews\"')"},
    {"not_zip.3mf", ErrorCode::kParse, "not_zip.3mf: not a 3MF file: it does not start with a zip signature ('PK')"},
    {"zip_without_model.3mf", ErrorCode::kParse,
     "zip_without_model.3mf: not a 3MF file: the zip holds no 3D model part (3D/3dmodel.model)"},
    {"truncated.step", ErrorCode::kParse,
     "truncated.step: STEP file truncated: it does not end with 'END-ISO-10303-21;'"},
    {"step_missing_parameter.step", ErrorCode::kParse,
     "step_missing_parameter.step:474: malformed STEP file: a parameter is missing after ',' (write $ for one left "
     "out)"},
    {"step_named.ply", ErrorCode::kParse,
     "step_named.ply: not a PLY file: it looks like a STEP file (name it .step to read it as one)"},
    {"off_bad_index.off", ErrorCode::kParse, "off_bad_index.off:16: OFF face 6 refers to vertex '8' of 8"},
    {"off_comment_among_faces.off", ErrorCode::kParse,
     "off_comment_among_faces.off:14: OFF line holds no data among the vertices and faces (a comment or spaces "
     "alone): assimp would read it as one"},
    {"off_not_numbers.off", ErrorCode::kParse, "off_not_numbers.off:4: OFF vertex 2 is not three or more numbers"},
    {"truncated.iges", ErrorCode::kParse,
     "truncated.iges: IGES file truncated: its last line is not a Terminate record ('T' in column 73)"},
};

class MalformedFile : public ::testing::TestWithParam<Refusal> {};

TEST_P(MalformedFile, isRefusedWithItsMessage) {
  const Refusal& c = GetParam();
  const Error e = refusalOf(c.file);
  EXPECT_EQ(int(e.code), int(c.code)) << e.message;
  if (std::string(c.message) == "<memory>") {
    // The limit depends on this machine's memory; the message names the grid and the need.
    EXPECT_EQ(
        e.message.rfind(std::string(c.file) + ": grid 16384 x 16384 x 16384 with 16384 occupied layers needs ", 0), 0u)
        << e.message;
  } else {
    EXPECT_EQ(e.message, c.message);
  }
}

INSTANTIATE_TEST_SUITE_P(Corpus, MalformedFile, ::testing::ValuesIn(kRefusals),
                         [](const ::testing::TestParamInfo<Refusal>& p) {
                           std::string n = p.param.file;
                           for (char& ch : n) {
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           }
                           return n;
                         });

TEST(MalformedCorpus, everyFileInTheFolderHasAnAssertion) {
  std::set<std::string> listed;
  for (const Refusal& r : kRefusals) listed.insert(r.file);
  for (const auto& entry : std::filesystem::directory_iterator(dataDir() / "malformed")) {
    EXPECT_TRUE(listed.count(entry.path().filename().string())) << entry.path() << " has no test";
  }
}

// ---- Quirks that must load ----

Result<StlLoad> quirk(const std::string& file) { return parseStl(bytesOf(dataDir() / "quirks" / file), file); }

TEST(StlQuirks, facetWithoutNormalLoads) {
  const auto r = quirk("ascii_missing_normal.stl");
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->mesh.triangles.size(), 1u);
  EXPECT_TRUE(r->ascii);
}

TEST(StlQuirks, zeroNormalLoads) {
  const auto r = quirk("ascii_zero_normal.stl");
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->mesh.triangles.size(), 1u);
}

TEST(StlQuirks, multipleSolidsLoadAsOneMeshNamedAfterTheFirst) {
  const auto r = quirk("ascii_multiple_solids.stl");
  ASSERT_TRUE(r.ok()) << r.error().message;
  ASSERT_EQ(r->mesh.triangles.size(), 2u);
  EXPECT_EQ(r->header, "a");
  EXPECT_EQ(r->mesh.triangles[1].v[0], glm::vec3(0, 0, 1));
}

TEST(StlQuirks, crlfThreeDigitExponentsPlusSignsAndBareEndsolidLoad) {
  const auto r = quirk("ascii_crlf_exponents_bare_endsolid.stl");
  ASSERT_TRUE(r.ok()) << r.error().message;
  ASSERT_EQ(r->mesh.triangles.size(), 1u);
  EXPECT_EQ(r->header, "cad");  // no trailing '\r'
  EXPECT_EQ(r->mesh.triangles[0].v[1], glm::vec3(1, 0, 0));
  EXPECT_EQ(r->mesh.triangles[0].v[2], glm::vec3(0, 0.25f, 100));
}

TEST(StlQuirks, uppercaseKeywordsAndTabsLoad) {
  const auto r = quirk("ascii_uppercase_tabs.stl");
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->mesh.triangles.size(), 1u);
  EXPECT_EQ(r->header, "T");
}

TEST(StlQuirks, degenerateTriangleIsKeptWithAWarning) {
  const auto r = quirk("ascii_degenerate.stl");
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->mesh.triangles.size(), 2u);
  EXPECT_EQ(r->topology.degenerate_triangles, 1);
  ASSERT_FALSE(r->warnings.empty());
  EXPECT_EQ(r->warnings[0], "ascii_degenerate.stl: 1 degenerate triangles (zero area; kept)");
}

TEST(StlQuirks, asciiOnOneLineWithoutFinalNewlineLoads) {
  const auto r = quirk("ascii_one_line.stl");
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_TRUE(r->ascii);
  EXPECT_EQ(r->mesh.triangles.size(), 2u);
  EXPECT_EQ(r->header, "one line");
  EXPECT_EQ(r->mesh.triangles[1].v[1], glm::vec3(1, 0, 0));
}

TEST(StlQuirks, binaryWithBytesAfterTheDeclaredTrianglesLoadsThemWithAWarning) {
  const auto r = quirk("binary_extra_bytes.stl");
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_FALSE(r->ascii);
  EXPECT_EQ(r->mesh.triangles.size(), 2u);
  ASSERT_FALSE(r->warnings.empty());
  EXPECT_EQ(r->warnings[0], "binary_extra_bytes.stl: 50 bytes after the 2 triangles the header declares were ignored");
}

TEST(StlQuirks, binaryWhoseHeaderStartsWithSolidIsBinary) {
  const auto r = quirk("binary_solid_header.stl");
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_FALSE(r->ascii);
  EXPECT_EQ(r->header, "solid part exported by a CAD tool");
  EXPECT_EQ(r->mesh.triangles.size(), 2u);
}

// 4^3 binvox with voxels 10..14 (binvox order) filled, i.e. x = 0, z = 2, y = 2, 3 and z = 3, y = 0, 1, 2.
void expectQuirkBinvoxVoxels(const VoxelGrid& g) {
  ASSERT_EQ(g.dims(), (Dims{4, 4, 4}));
  EXPECT_EQ(g.filledCount(), 5);
  EXPECT_TRUE(g.get(0, 2, 2));
  EXPECT_TRUE(g.get(0, 3, 2));
  EXPECT_TRUE(g.get(0, 0, 3));
  EXPECT_TRUE(g.get(0, 1, 3));
  EXPECT_TRUE(g.get(0, 2, 3));
}

TEST(BinvoxQuirks, fileWithoutTranslateAndScaleReadsWithOriginZeroAndScaleOne) {
  const auto r = decodeBinvox(bytesOf(dataDir() / "quirks" / "cuda_voxelizer_style.binvox"), "c.binvox");
  ASSERT_TRUE(r.ok()) << r.error().message;
  expectQuirkBinvoxVoxels(r.value());
  EXPECT_EQ(r->frame().origin, glm::dvec3(0.0));
  EXPECT_EQ(r->frame().voxel_size, 0.25);
}

TEST(BinvoxQuirks, crlfHeaderLinesRead) {
  const auto r = decodeBinvox(bytesOf(dataDir() / "quirks" / "crlf_header.binvox"), "c.binvox");
  ASSERT_TRUE(r.ok()) << r.error().message;
  expectQuirkBinvoxVoxels(r.value());
  EXPECT_EQ(r->frame().origin, glm::dvec3(0.5, -1, 2));
  EXPECT_EQ(r->frame().voxel_size, 1.0);
}

TEST(VxmQuirks, fileWrittenFromTheFormatDocumentDecodes) {
  // tests/data/make_io_data.py writes sample.vxm from docs/file-format.md alone.
  const std::vector<uint8_t> bytes = bytesOf(dataDir() / "quirks" / "sample.vxm");
  const auto r = decodeVxm(bytes, "sample.vxm");
  ASSERT_TRUE(r.ok()) << r.error().message;
  const VoxelGrid& g = r.value();
  ASSERT_EQ(g.dims(), (Dims{3, 2, 2}));
  EXPECT_EQ(g.frame().origin, glm::dvec3(1, 2, 3));
  EXPECT_EQ(g.frame().voxel_size, 0.25);
  EXPECT_EQ(g.frame().units, "mm");
  EXPECT_EQ(g.frame().source, "part.stl");
  // Runs 1 empty, 2 filled, 4 empty, 5 filled over x-fastest order: indices 1, 2 and 7..11.
  for (int64_t i = 0; i < 12; ++i) {
    const glm::ivec3 c = g.coordinates(i);
    EXPECT_EQ(g.get(c.x, c.y, c.z), i == 1 || i == 2 || i >= 7) << i;
  }
  // Our encoder writes the same bytes.
  EXPECT_EQ(encodeVxm(g), bytes);
}

}  // namespace
}  // namespace vox::io
