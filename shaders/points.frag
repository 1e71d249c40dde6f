#version 330 core
// Flat-coloured points. Built twice: as is (square points), and with VOX_ROUND_POINTS defined (thesis 6.2 "point
// smooth": fragments outside the inscribed circle of the point sprite are discarded). Two programs instead of a
// uniform branch because a shader that may discard costs llvmpipe about 20% more per point even when it does not.

flat in vec3 v_colour;
out vec4 frag_colour;

void main() {
#ifdef VOX_ROUND_POINTS
  vec2 d = gl_PointCoord - vec2(0.5);
  if (dot(d, d) > 0.25) discard;
#endif
  frag_colour = vec4(v_colour, 1.0);
}
