#pragma once
// Sample distribution shadow maps (Lauritzen, Salvi and Lefohn, I3D 2011, [Lauritzen2011]), GL-free
// (lessons/10_showdown/sdsm renders them): the cascades of algorithms/cascades, but split over the
// depths the camera actually sees instead of [near, deepest point of the scene], and each cascade's
// map fitted to the points of its slice that are on screen instead of the whole slice of the view
// frustum.
//
// What the GPU hands over is the camera's depth buffer reduced to tiles (a tile: a block of pixels,
// the nearest and farthest view depth drawn in it): depthRange gives the range to split (the
// practical scheme's lambda over [nearest, farthest]); tileReceivers rebuilds, from each tile and a
// cascade's depth interval, the corners of the tile's piece of the view frustum there: the points
// that cascade's map must cover (a conservative stand-in for the samples themselves).
#include <vector>

#include <glm/glm.hpp>

#include "algorithms/cascades.hpp"

namespace shadowlab::shadow {

// The camera's depth buffer reduced to tiles of `tilePixels` x `tilePixels` pixels (the last row
// and column may be narrower), row 0 at the bottom as GL reads it.
struct DepthTiles {
  int width = 0, height = 0;           // tiles across and up
  int tilePixels = 1;                  // a tile's side in pixels
  int pixelsWide = 0, pixelsHigh = 0;  // the frame the depths were drawn into
  std::vector<glm::vec2> depths;       // per tile (nearest, farthest) view depth; x > y: nothing drawn there
  CascadeViewer viewer;                // the camera the depths were drawn from (frames old with a latency)
};

// The nearest and farthest depth over the tiles, and how many tiles saw anything (0: a frame of
// sky, and nearest > farthest). Throws std::invalid_argument when the tiles do not match their size.
struct DepthRange {
  double nearest = 0.0, farthest = 0.0;
  int tiles = 0;
};
DepthRange depthRange(const DepthTiles& tiles);

// Appends the world-space corners of tile (x, y)'s piece of its viewer's frustum between view depths
// a and b (8 points).
void tileCorners(const DepthTiles& tiles, int x, int y, double a, double b, std::vector<glm::vec3>& out);

struct SdsmOptions {
  CascadeOptions cascades;  // count, lambda, the per-cascade fit, the caster culling, a student's splitter
  double band = 0.1;        // the blend band: cascade i + 1 also covers this fraction of cascade i's range
  bool tightFit = true;     // each cascade's map fitted to its tiles' points (off: to its whole slice)
  double margin = 0.01;     // the range widened by this fraction each way (depth-buffer rounding)
};

struct SdsmFit {
  CascadeSet set;
  DepthRange range;                // what the tiles held
  double zNear = 0.0, zFar = 0.0;  // the range split (the tiles' widened by the margin, within the viewer's)
  bool fellBack = false;           // no tile saw anything: the practical splits over [near, deepest point of the scene]
};

// The cascades of a directional light travelling along `direction` for `viewer` (this frame's
// camera) from `tiles` (the depths of the frame they were drawn in). Throws as fitCascades does.
SdsmFit fitSampleDistribution(const glm::vec3& direction, const CasterBoxes& scene, const CascadeViewer& viewer,
                              const DepthTiles& tiles, const SdsmOptions& options);

}  // namespace shadowlab::shadow
