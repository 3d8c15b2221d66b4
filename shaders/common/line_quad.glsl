// A debug line as a screen-space quad uWidth pixels wide (core profile OpenGL draws GL_LINES one
// pixel wide, too thin on a projector). Drawn by a geometry shader where there is one
// (common/lines.geom) and, where there is none (WebGL2), by a vertex shader that is given both
// ends at each of the quad's corners (common/lines_quad.vert): the same maths either way.

// Clips the segment a-b (clip space) to the near plane (z >= -w) so that a line passing behind the
// camera does not flip across the screen. False when all of it is behind.
bool clipToNear(inout vec4 a, inout vec4 b) {
  float da = a.z + a.w, db = b.z + b.w;  // signed distance to the near plane, in clip units
  if (da < 0.0 && db < 0.0) return false;
  if (da < 0.0) a = mix(a, b, da / (da - db));
  if (db < 0.0) b = mix(b, a, db / (db - da));
  return true;
}

// Corner `corner` (0, 1 at a; 2, 3 at b) of the quad, extended by half a width at both ends so
// that the corners of boxes and frusta close; counter-clockwise on screen whichever way the segment
// runs, so face culling keeps it.
vec4 lineQuadCorner(vec4 a, vec4 b, int corner, vec2 viewport, float width) {
  vec2 halfViewport = 0.5 * viewport;
  vec2 sa = a.xy / a.w * halfViewport, sb = b.xy / b.w * halfViewport;
  vec2 along = sb - sa;
  along = dot(along, along) > 1e-12 ? normalize(along) : vec2(1.0, 0.0);
  vec2 across = vec2(-along.y, along.x);
  vec2 h = 0.5 * width / halfViewport;  // half a width, in NDC units per axis
  vec2 offset = corner == 0 ? -along + across : corner == 1 ? -along - across : corner == 2 ? along + across
                                                                                            : along - across;
  vec4 p = corner < 2 ? a : b;
  return vec4(p.xy + offset * h * p.w, p.zw);
}
