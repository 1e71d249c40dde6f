#version 330 core
// Flat-coloured points; optionally round (thesis 6.2 "point smooth"): fragments outside the inscribed circle of
// the point sprite are discarded, so neighbouring points overlap into a smoother silhouette.

flat in vec3 v_colour;
uniform bool u_round;
out vec4 frag_colour;

void main() {
  if (u_round) {
    vec2 d = gl_PointCoord - vec2(0.5);
    if (dot(d, d) > 0.25) discard;
  }
  frag_colour = vec4(v_colour, 1.0);
}
