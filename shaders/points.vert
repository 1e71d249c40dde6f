#version 330 core
// Surface-voxel point renderer (thesis 5.1 and 6.2): one point per surface voxel, its intensity looked up by the
// 6-bit face-neighbour code in a 64-entry table, its size the projected size of one voxel in pixels.
// Inputs follow vox::render::PackedPoint (8 bytes): uint16 x, y, z (glVertexAttribIPointer, GL_UNSIGNED_SHORT)
// and uint8 code, uint8 flags (GL_UNSIGNED_BYTE).

layout(location = 0) in uvec3 a_voxel;
layout(location = 1) in uvec2 a_code_flags;

uniform mat4 u_view_proj;       // voxel-index space (voxel (i,j,k) spans [i,i+1) x [j,j+1) x [k,k+1)) to clip space
uniform float u_scale;          // fine voxels per point coordinate: 1, or 2^level for a level-of-detail point set
uniform float u_intensity[64];  // intensity per neighbour code, 0..1
uniform vec3 u_material;        // colour of an intensity-1 surface point
uniform vec3 u_cut_colour;      // colour of the section (cut-face) points, already shaded
uniform float u_point_scale;    // point size in pixels times clip w: diameter_px = u_point_scale / w
uniform float u_fixed_size;     // > 0: use this point size in pixels instead
uniform int u_section_axis;     // -1: no section; 0, 1, 2: cut perpendicular to X, Y, Z
uniform int u_section_index;    // the section plane, in point coordinates (voxel index / u_scale)
uniform bool u_section_keep_below;  // keep coordinates < index (true) or > index (false)

flat out vec3 v_colour;

const uint kFlagCut = 1u;

void main() {
  bool cut = (a_code_flags.y & kFlagCut) != 0u;
  if (u_section_axis >= 0 && !cut) {
    int c = int(a_voxel[u_section_axis]);
    bool keep = u_section_keep_below ? c < u_section_index : c > u_section_index;
    if (!keep) {
      // Outside the clip volume: point primitives are culled by their centre, so nothing is rasterised.
      gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
      gl_PointSize = 1.0;
      v_colour = vec3(0.0);
      return;
    }
  }
  vec3 p = (vec3(a_voxel) + 0.5) * u_scale;
  gl_Position = u_view_proj * vec4(p, 1.0);
  gl_PointSize = u_fixed_size > 0.0 ? u_fixed_size : clamp(u_point_scale / gl_Position.w, 1.0, 255.0);
  v_colour = cut ? u_cut_colour : u_material * u_intensity[a_code_flags.x & 63u];
}
