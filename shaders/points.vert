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
// The section (vox::SectionPlane, vox/core/section_plane.h, in point coordinates): a point whose centre c has
// s = dot(normal, c) - offset below -half is below the plane's slab, at half or more above it.
uniform bool u_section_on;
uniform vec4 u_section_plane;       // normal, offset
uniform float u_section_half;
uniform bool u_section_keep_below;  // keep the points below the slab (true) or above it (false)
// Colour by a scalar volume (PointRenderer::setScalarVolume): GL_R8 texels over a box of voxels, 0 = no value,
// 1..255 = 0..1 along the ramp; values under u_scalar_threshold (0..1) are red.
uniform bool u_scalar_on;
uniform sampler3D u_scalar;
uniform ivec3 u_scalar_min;
uniform ivec3 u_scalar_dims;
uniform float u_scalar_threshold;

flat out vec3 v_colour;

const uint kFlagCut = 1u;

// io::rampColour (src/io/figure.cpp): dark blue, blue, teal, green, yellow at 0, 0.25, 0.5, 0.75, 1.
vec3 ramp(float t) {
  const vec3 c0 = vec3(30.0, 20.0, 90.0) / 255.0, c1 = vec3(35.0, 90.0, 165.0) / 255.0;
  const vec3 c2 = vec3(30.0, 155.0, 150.0) / 255.0, c3 = vec3(140.0, 200.0, 70.0) / 255.0;
  const vec3 c4 = vec3(250.0, 230.0, 50.0) / 255.0;
  t = clamp(t, 0.0, 1.0) * 4.0;
  if (t < 1.0) return mix(c0, c1, t);
  if (t < 2.0) return mix(c1, c2, t - 1.0);
  if (t < 3.0) return mix(c2, c3, t - 2.0);
  return mix(c3, c4, t - 3.0);
}

// The scalar of a fine voxel: -1 without one.
float scalarAt(ivec3 v) {
  ivec3 i = v - u_scalar_min;
  if (any(lessThan(i, ivec3(0))) || any(greaterThanEqual(i, u_scalar_dims))) return -1.0;
  float raw = texelFetch(u_scalar, i, 0).r * 255.0;
  return raw < 0.5 ? -1.0 : (raw - 1.0) / 254.0;
}

// A point's colour from the scalar volume; a coarse point (u_scale > 1) looks at its corner and centre voxels.
vec3 scalarColour(vec3 shaded_material, float intensity) {
  ivec3 corner = ivec3(a_voxel) * int(u_scale);
  float t = scalarAt(corner + ivec3(int(u_scale) / 2));
  if (t < 0.0) t = scalarAt(corner);
  if (t < 0.0) return shaded_material;
  vec3 base = t < u_scalar_threshold ? vec3(0.95, 0.12, 0.10) : ramp(t);
  return base * intensity;
}

void main() {
  bool cut = (a_code_flags.y & kFlagCut) != 0u;
  if (u_section_on && !cut) {
    vec3 c = vec3(a_voxel) + 0.5;
    vec3 n = u_section_plane.xyz;
    float s = n.x * c.x + n.y * c.y + n.z * c.z - u_section_plane.w;
    bool keep = u_section_keep_below ? s < -u_section_half : s >= u_section_half;
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
  float intensity = u_intensity[a_code_flags.x & 63u];
  v_colour = cut ? u_cut_colour : u_material * intensity;
  if (u_scalar_on && !cut) v_colour = scalarColour(v_colour, intensity);
}
