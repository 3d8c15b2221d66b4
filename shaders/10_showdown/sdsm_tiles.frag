#version 410 core
// Sample distribution shadow maps, the reduction's first step (lessons/10_showdown/sdsm): each
// output texel is a tile of uTile x uTile pixels of the camera's depth buffer, and holds the nearest
// and the farthest VIEW depth drawn there. Depths are positive floats, whose bit patterns order as
// the numbers do: stored as uints they reduce with min and max exactly and need no float target
// (WebGL2 renders to float textures only with an extension). Nothing drawn (depth 1, the clear):
// (+inf, 0), which every later min and max leaves alone.
uniform sampler2D uDepth;  // the camera's depth buffer (a depth texture, read with texelFetch)
uniform ivec2 uSize;       // its pixels
uniform int uTile;
uniform float uNear, uFar;  // the camera's planes: window depth back to view depth

layout(location = 0) out uvec4 outRange;

const uint kEmpty = 0x7F800000u;  // +inf

void main() {
  ivec2 base = ivec2(gl_FragCoord.xy) * uTile;
  uint nearest = kEmpty, farthest = 0u;
  for (int y = 0; y < uTile; ++y)
    for (int x = 0; x < uTile; ++x) {
      ivec2 p = base + ivec2(x, y);
      if (p.x >= uSize.x || p.y >= uSize.y) continue;
      float d = texelFetch(uDepth, p, 0).r;
      if (d >= 1.0) continue;
      float ndc = 2.0 * d - 1.0;  // glm::perspective's depth, -1 at near, 1 at far
      float z = 2.0 * uNear * uFar / (uFar + uNear - ndc * (uFar - uNear));
      uint bits = floatBitsToUint(z);
      nearest = min(nearest, bits);
      farthest = max(farthest, bits);
    }
  outRange = uvec4(nearest, farthest, 0u, 0u);
}
