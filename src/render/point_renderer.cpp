// Point renderer (thesis 5.1: intensity by neighbour code; thesis 6.2: voxels displayed as points whose size follows
// the zoom and the resolution). Draws code groups in one glMultiDrawArrays call, skipping groups that face away.
#include "vox/render/point_renderer.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>

#include "vox/render/gl.h"
#include "vox_render_shaders.h"

namespace vox::render {
namespace {

GLuint compileShader(GLenum type, const char* source, std::string& log) {
  GLuint s = glCreateShader(type);
  glShaderSource(s, 1, &source, nullptr);
  glCompileShader(s);
  GLint ok = GL_FALSE;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint len = 0;
    glGetShaderiv(s, GL_INFO_LOG_LENGTH, &len);
    std::string text(size_t(std::max(len, 1)), '\0');
    glGetShaderInfoLog(s, len, nullptr, text.data());
    log = text.c_str();
    glDeleteShader(s);
    return 0;
  }
  return s;
}

// Points the VAO's two attributes at a buffer of PackedPoint (layout documented in points.vert).
void setPointAttributes(GLuint vao, GLuint vbo) {
  glBindVertexArray(vao);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glEnableVertexAttribArray(0);
  glVertexAttribIPointer(0, 3, GL_UNSIGNED_SHORT, sizeof(PackedPoint), reinterpret_cast<const void*>(0));
  glEnableVertexAttribArray(1);
  glVertexAttribIPointer(1, 2, GL_UNSIGNED_BYTE, sizeof(PackedPoint),
                         reinterpret_cast<const void*>(offsetof(PackedPoint, code)));
}

// Uploads `n` points into `vbo`, growing its storage (with headroom for later edits) only when needed: llvmpipe
// buffers live in ordinary memory, so a sub-data copy runs at memcpy speed while new storage costs page faults.
void uploadPoints(GLuint vbo, int64_t& capacity, const PackedPoint* points, int64_t n) {
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  const auto bytes = [](int64_t count) { return GLsizeiptr(count * int64_t(sizeof(PackedPoint))); };
  if (n > capacity || n < capacity / 4) {
    capacity = std::max<int64_t>(n + n / 8, 1);
    glBufferData(GL_ARRAY_BUFFER, bytes(capacity), nullptr, GL_DYNAMIC_DRAW);
  }
  if (n > 0) glBufferSubData(GL_ARRAY_BUFFER, 0, bytes(n), points);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

// The code a voxel has when its only free face is the cut face: shades the section like a flat face.
uint8_t cutFaceCode(const CutAway& section) {
  // kBelow keeps coordinates < index, so the cut face looks towards +axis; kAbove towards -axis. A plane at an angle
  // is shaded as the face of its normal's largest component.
  SectionAxis axis = section.axis;
  bool plus = section.side == SectionSide::kBelow;
  if (axis == SectionAxis::kPlane) {
    const int a = dominantAxis(section.normal);
    axis = SectionAxis(a + 1);
    plus = plus == (section.normal[a] > 0.0f);
  }
  uint8_t bit = 0;
  switch (axis) {
    case SectionAxis::kX:
      bit = plus ? 8 : 16;
      break;
    case SectionAxis::kY:
      bit = plus ? 4 : 32;
      break;
    case SectionAxis::kZ:
      bit = plus ? 1 : 2;
      break;
    case SectionAxis::kNone:
    case SectionAxis::kPlane:
      break;
  }
  return uint8_t(63 & ~bit);
}

// Compiles and links points.vert with points.frag, the latter with `defines` inserted after its #version line.
Result<GLuint> buildProgram(const std::string& defines) {
  std::string log;
  const GLuint vs = compileShader(GL_VERTEX_SHADER, shaders::kPointsVert, log);
  if (!vs) return makeError(ErrorCode::kNoOpenGL, "points.vert does not compile:\n" + log);
  std::string frag = shaders::kPointsFrag;
  frag.insert(frag.find('\n') + 1, defines);
  const GLuint fs = compileShader(GL_FRAGMENT_SHADER, frag.c_str(), log);
  if (!fs) {
    glDeleteShader(vs);
    return makeError(ErrorCode::kNoOpenGL, "points.frag (" + defines + ") does not compile:\n" + log);
  }
  const GLuint program = glCreateProgram();
  glAttachShader(program, vs);
  glAttachShader(program, fs);
  glLinkProgram(program);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint len = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &len);
    std::string text(size_t(std::max(len, 1)), '\0');
    glGetProgramInfoLog(program, len, nullptr, text.data());
    glDeleteProgram(program);
    return makeError(ErrorCode::kNoOpenGL, std::string("point shaders do not link:\n") + text.c_str());
  }
  return program;
}

}  // namespace

Result<std::unique_ptr<PointRenderer>> PointRenderer::create() {
  if (!glGetString(GL_VERSION)) return makeError(ErrorCode::kNoOpenGL, "no current OpenGL context");
  auto square = buildProgram("");
  if (!square) return square.error();
  auto round = buildProgram("#define VOX_ROUND_POINTS 1\n");
  if (!round) {
    glDeleteProgram(*square);
    return round.error();
  }
  std::unique_ptr<PointRenderer> r(new PointRenderer());
  r->programs_ = {*square, *round};
  glGenVertexArrays(1, &r->vao_);
  glGenVertexArrays(1, &r->cut_vao_);
  glGenBuffers(1, &r->cut_vbo_);
  for (Level& lvl : r->levels_) glGenBuffers(1, &lvl.vbo);
  setPointAttributes(r->cut_vao_, r->cut_vbo_);
  glBindVertexArray(0);
  return r;
}

PointRenderer::~PointRenderer() {
  for (Level& lvl : levels_) {
    if (lvl.vbo) glDeleteBuffers(1, &lvl.vbo);
  }
  if (cut_vbo_) glDeleteBuffers(1, &cut_vbo_);
  if (vao_) glDeleteVertexArrays(1, &vao_);
  if (cut_vao_) glDeleteVertexArrays(1, &cut_vao_);
  clearScalarVolume();
  for (GLuint p : programs_) {
    if (p) glDeleteProgram(p);
  }
}

Status PointRenderer::setScalarVolume(glm::ivec3 box_min, Dims box_dims, const std::vector<uint8_t>& values) {
  clearScalarVolume();
  if (int64_t(values.size()) != box_dims.count()) {
    return makeError(ErrorCode::kInvalidArgument, "scalar volume: the values do not fill the box");
  }
  GLint most = 0;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &most);
  if (box_dims.nx > most || box_dims.ny > most || box_dims.nz > most) {
    return makeError(ErrorCode::kLimit, "the " + std::to_string(box_dims.nx) + " x " + std::to_string(box_dims.ny) +
                                            " x " + std::to_string(box_dims.nz) +
                                            " voxel box is larger than this OpenGL's 3D textures (" +
                                            std::to_string(most) + " per side)");
  }
  if (box_dims.count() == 0) return Ok{};
  glGenTextures(1, &scalar_texture_);
  glBindTexture(GL_TEXTURE_3D, scalar_texture_);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_R8, box_dims.nx, box_dims.ny, box_dims.nz, 0, GL_RED, GL_UNSIGNED_BYTE,
               values.data());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glBindTexture(GL_TEXTURE_3D, 0);
  if (glGetError() != GL_NO_ERROR) {
    clearScalarVolume();
    return makeError(ErrorCode::kNoOpenGL, "the scalar volume could not be uploaded (out of texture memory?)");
  }
  scalar_min_ = box_min;
  scalar_dims_ = glm::ivec3(box_dims.nx, box_dims.ny, box_dims.nz);
  return Ok{};
}

void PointRenderer::clearScalarVolume() {
  if (scalar_texture_) glDeleteTextures(1, &scalar_texture_);
  scalar_texture_ = 0;
  scalar_dims_ = glm::ivec3(0);
}

void PointRenderer::setGrid(const VoxelGrid& grid) {
  Level& base = levels_[0];
  base.grid = grid;  // shares the layers (copy on write)
  base.cloud.build(base.grid);
  base.built = true;
  for (size_t k = 1; k < levels_.size(); ++k) {
    levels_[k].built = false;  // rebuilt from the new grid on first use
    levels_[k].grid = VoxelGrid();
    levels_[k].cloud = PointCloud();
    levels_[k].uploaded_version = ~uint64_t(0);  // a new cloud's versions restart: never match the old upload
  }
  bounds_ = base.cloud.bounds();
  ++grid_version_;
}

void PointRenderer::updateLayers(const VoxelGrid& grid, int32_t z0, int32_t z1) {
  Level& base = levels_[0];
  if (!base.built || grid.dims() != base.grid.dims()) {
    setGrid(grid);
    return;
  }
  base.grid = grid;
  base.cloud.rebuildLayers(base.grid, z0, z1);
  // Coarse level k's layer z covers level k-1's layers 2z and 2z+1.
  for (size_t k = 1; k < levels_.size() && levels_[k].built; ++k) {
    z0 = std::max(0, z0) / 2;
    z1 = (z1 + 1) / 2;
    downsample2Layers(levels_[k - 1].grid, levels_[k].grid, z0, z1);
    levels_[k].cloud.rebuildLayers(levels_[k].grid, z0, z1);
  }
  bounds_ = base.cloud.bounds();
  ++grid_version_;
}

Box3 PointRenderer::bounds() const { return bounds_; }

void PointRenderer::prepare() {
  Level& base = levels_[0];
  if (base.built && base.uploaded_version != base.cloud.version()) upload(base);
}

PointRenderer::Level& PointRenderer::level(int k) {
  Level& lvl = levels_[size_t(k)];
  if (!lvl.built) {
    const Level& finer = level(k - 1);
    lvl.grid = downsample2(finer.grid);
    lvl.cloud.build(lvl.grid);
    lvl.built = true;
  }
  return lvl;
}

void PointRenderer::upload(Level& lvl) {
  lvl.cloud.assemble(lvl.buffer);
  uploadPoints(lvl.vbo, lvl.vbo_capacity, lvl.buffer.points.data(), int64_t(lvl.buffer.points.size()));
  // The GPU holds the points now; keep only the group offsets.
  lvl.buffer.points = std::vector<PackedPoint>();
  lvl.uploaded_version = lvl.cloud.version();
}

namespace {

// Depth test on; a see-through pass (opacity < 1: a ghost of the whole part around a peeled one) is blended with what
// is drawn, tested against its depth but leaving it as it is.
void setDepthAndBlending(float opacity) {
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  if (opacity < 1.0f) {
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendColor(0.0f, 0.0f, 0.0f, std::clamp(opacity, 0.0f, 1.0f));
    glBlendFunc(GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA);
  } else {
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
  }
}

// The visible groups' points as ranges of the buffer, adjacent groups merged into one range each; counted in stats.
void visibleRanges(const PointBuffer& buffer, const std::array<bool, kCodeGroups>& visible, std::vector<GLint>& firsts,
                   std::vector<GLsizei>& counts, DrawStats& stats) {
  for (int c = 0; c < kCodeGroups; ++c) {
    const int64_t n = buffer.groupSize(c);
    if (!visible[size_t(c)] || n == 0) continue;
    const auto first = GLint(buffer.group_first[size_t(c)]);
    if (!firsts.empty() && firsts.back() + counts.back() == first) {
      counts.back() += GLsizei(n);
    } else {
      firsts.push_back(first);
      counts.push_back(GLsizei(n));
    }
    stats.points_drawn += n;
    ++stats.groups_drawn;
  }
}

}  // namespace

DrawStats PointRenderer::draw(const Camera& camera, int32_t width, int32_t height, const DrawParams& params) {
  DrawStats stats;
  if (!levels_[0].built || width < 1 || height < 1) return stats;

  // Level of detail: the smallest downsampled set within the budget (each level has about 1/4 of the points).
  int k = 0;
  if (params.coarse) {
    while (k + 1 < int(levels_.size()) && level(k).cloud.size() > params.lod_point_budget) ++k;
  }
  Level& lvl = level(k);
  if (lvl.uploaded_version != lvl.cloud.version()) upload(lvl);
  const double scale = double(1 << k);
  stats.lod_level = k;
  stats.points_available = lvl.cloud.size();

  const double aspect = double(width) / double(height);
  const glm::dvec2 range = camera.depthRange(bounds_);
  const glm::dmat4 proj = camera.projectionMatrix(aspect, range.x, range.y);
  const glm::dmat4 view = camera.viewMatrix();
  const glm::mat4 view_proj(proj * view);

  // Tables: classic is fixed; lit takes the view-space light into world space with the inverse view rotation.
  IntensityTable table;
  if (params.lut == Lut::kClassic) {
    table = classicTable();
  } else {
    const glm::dvec3 light_world = glm::transpose(glm::dmat3(view)) * params.light_dir_view;
    table = litTable(light_world, params.ambient);
  }
  const glm::vec3 colour =
      params.colour ? *params.colour
                    : (params.lut == Lut::kClassic ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(0.78f, 0.84f, 0.92f));

  // Projected size of one point (2^k voxels) in pixels is proj[1][1] * (height / 2) * scale / w_clip.
  const double coverage = pointCoverageFactor(camera, params.round_points, aspect);
  const double point_scale = coverage * scale * proj[1][1] * double(height) * 0.5;
  const double depth_at_target = camera.projection == Projection::kPerspective ? camera.distance : 1.0;
  stats.point_size_px =
      params.point_size_px > 0.0 ? params.point_size_px : std::clamp(point_scale / depth_at_target, 1.0, 255.0);

  const CutAway& section = params.section;
  const SectionPlane plane = sectionPlane(section, k);  // indices >= 0 (validated by callers)

  const GLuint program = programs_[params.round_points ? 1 : 0];
  glUseProgram(program);
  auto loc = [&](const char* name) { return glGetUniformLocation(program, name); };
  glUniformMatrix4fv(loc("u_view_proj"), 1, GL_FALSE, glm::value_ptr(view_proj));
  glUniform1f(loc("u_scale"), float(scale));
  glUniform1fv(loc("u_intensity"), 64, table.data());
  glUniform3fv(loc("u_material"), 1, glm::value_ptr(colour));
  const glm::vec3 cut_colour = params.cut_colour * table[cutFaceCode(section)];
  glUniform3fv(loc("u_cut_colour"), 1, glm::value_ptr(cut_colour));
  glUniform1f(loc("u_point_scale"), float(point_scale));
  glUniform1f(loc("u_fixed_size"), float(params.point_size_px));
  glUniform1i(loc("u_section_on"), section.active() ? 1 : 0);
  glUniform4f(loc("u_section_plane"), plane.normal.x, plane.normal.y, plane.normal.z, plane.offset);
  glUniform1f(loc("u_section_half"), plane.half);
  glUniform1i(loc("u_section_keep_below"), section.side == SectionSide::kBelow ? 1 : 0);
  const bool scalar = params.scalar_colour && scalar_texture_ != 0;
  glUniform1i(loc("u_scalar_on"), scalar ? 1 : 0);
  if (scalar) {
    glActiveTexture(GL_TEXTURE1);  // unit 0 is ImGui's
    glBindTexture(GL_TEXTURE_3D, scalar_texture_);
    glActiveTexture(GL_TEXTURE0);
    glUniform1i(loc("u_scalar"), 1);
    glUniform3i(loc("u_scalar_min"), scalar_min_.x, scalar_min_.y, scalar_min_.z);
    glUniform3i(loc("u_scalar_dims"), scalar_dims_.x, scalar_dims_.y, scalar_dims_.z);
    glUniform1f(loc("u_scalar_threshold"), params.scalar_threshold);
  }

  setDepthAndBlending(params.opacity);
  glEnable(GL_PROGRAM_POINT_SIZE);

  // Group culling, then adjacent visible groups merged into one range each.
  std::array<bool, kCodeGroups> visible{};
  if (params.cull_back_groups) {
    visible = visibleCodes(visibleFaceDirections(camera, bounds_));
  } else {
    visible.fill(true);
  }
  std::vector<GLint> firsts;
  std::vector<GLsizei> counts;
  visibleRanges(lvl.buffer, visible, firsts, counts, stats);
  if (!firsts.empty()) {
    setPointAttributes(vao_, lvl.vbo);
    glMultiDrawArrays(GL_POINTS, firsts.data(), counts.data(), GLsizei(firsts.size()));
  }

  if (section.active()) {
    if (!(cut_section_ == section) || cut_level_ != k || cut_version_ != grid_version_) {
      CutAway at_level = section;
      at_level.index = section.index >> k;
      at_level.offset = plane.offset;
      const std::vector<PackedPoint> cut = sectionPoints(lvl.grid, at_level);
      uploadPoints(cut_vbo_, cut_capacity_, cut.data(), int64_t(cut.size()));
      cut_section_ = section;
      cut_level_ = k;
      cut_version_ = grid_version_;
      cut_count_ = int64_t(cut.size());
    }
    if (cut_count_ > 0) {
      glBindVertexArray(cut_vao_);
      glDrawArrays(GL_POINTS, 0, GLsizei(cut_count_));
    }
    stats.cut_points = cut_count_;
  }
  glBindVertexArray(0);
  glUseProgram(0);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  return stats;
}

}  // namespace vox::render
