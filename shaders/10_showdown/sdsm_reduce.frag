#version 410 core
// Sample distribution shadow maps, the reduction's later steps (lessons/10_showdown/sdsm): each
// output texel the nearest and farthest depth of 2 x 2 texels of the level below (sdsm_tiles.frag
// says how they are stored), until the tiles are few enough to read back.
uniform usampler2D uTiles;
uniform ivec2 uSize;  // the level below, in texels

layout(location = 0) out uvec4 outRange;

void main() {
  ivec2 base = ivec2(gl_FragCoord.xy) * 2;
  uint nearest = 0x7F800000u, farthest = 0u;
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x) {
      ivec2 p = base + ivec2(x, y);
      if (p.x >= uSize.x || p.y >= uSize.y) continue;
      uvec2 r = texelFetch(uTiles, p, 0).xy;
      nearest = min(nearest, r.x);
      farthest = max(farthest, r.y);
    }
  outRange = uvec4(nearest, farthest, 0u, 0u);
}
