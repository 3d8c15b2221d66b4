#include "core/texture_gen.hpp"

#include <algorithm>
#include <cmath>

#include "core/mesh_gen.hpp"

namespace shadowlab {

namespace {

Image8 blank(int size, int channels, std::uint8_t fill = 0) {
  Image8 image;
  image.width = image.height = size;
  image.channels = channels;
  image.data.assign(std::size_t(size) * size * channels, fill);
  return image;
}

std::uint8_t toByte(float v) { return std::uint8_t(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f); }

void setRgb(Image8& image, int x, int y, const glm::vec3& c) {
  std::uint8_t* p = image.at(x, y);
  p[0] = toByte(c.x);
  p[1] = toByte(c.y);
  p[2] = toByte(c.z);
}

int wrap(int v, int period) { return ((v % period) + period) % period; }

// Value noise on a lattice that repeats every `period` cells, so textures tile.
float tilingNoise(float x, float y, int period, std::uint64_t seed) {
  const float fx = std::floor(x), fy = std::floor(y);
  const int ix = int(fx), iy = int(fy);
  float tx = x - fx, ty = y - fy;
  tx = tx * tx * (3.0f - 2.0f * tx);
  ty = ty * ty * (3.0f - 2.0f * ty);
  auto v = [&](int dx, int dy) {
    return float(hashCell(wrap(ix + dx, period), wrap(iy + dy, period), seed) >> 40) * (1.0f / 16777215.0f);
  };
  const float a = v(0, 0) + (v(1, 0) - v(0, 0)) * tx;
  const float b = v(0, 1) + (v(1, 1) - v(0, 1)) * tx;
  return a + (b - a) * ty;
}

// fBm of tilingNoise over [0,1)^2 texture space, `cells` lattice cells across at the first octave.
float tilingFbm(float u, float v, int cells, int octaves, std::uint64_t seed) {
  float sum = 0.0f, amplitude = 1.0f, norm = 0.0f;
  for (int o = 0; o < octaves; ++o) {
    sum += amplitude * tilingNoise(u * float(cells), v * float(cells), cells, seed + std::uint64_t(o) * 7919u);
    norm += amplitude;
    amplitude *= 0.5f;
    cells *= 2;
  }
  return sum / norm;
}

float smoothstep(float e0, float e1, float x) {
  const float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// ---- bricks: one layout shared by the colour and the normal map --------------------------------
struct BrickSample {
  float height;      // 0 in mortar, 1 on a brick face, ramps over the bevel
  std::uint64_t id;  // which brick (for colour variation)
};

BrickSample brickAt(float u, float v) {
  constexpr int kRows = 16, kPerRow = 8;
  const float rowF = v * kRows;
  const int row = int(std::floor(rowF));
  // Running bond: every other row shifts by half a brick.
  float colF = u * kPerRow + ((row & 1) ? 0.5f : 0.0f);
  const int col = int(std::floor(colF));
  const float fx = colF - float(col), fy = rowF - float(row);
  // Distance to the brick's edge in brick-height units (a brick is 2 units wide, 1 tall).
  const float edge = std::min(std::min(fx, 1.0f - fx) * 2.0f, std::min(fy, 1.0f - fy));
  const float mortar = 0.08f, bevel = 0.12f;
  BrickSample s;
  s.height = smoothstep(mortar, mortar + bevel, edge);
  s.id = hashCell(wrap(col, kPerRow), wrap(row, kRows), 0xB51C);
  return s;
}

float brickSurface(float u, float v, std::uint64_t seed) {
  const BrickSample s = brickAt(u, v);
  // Grain: bricks are rough, mortar rougher and lower.
  return s.height + 0.05f * tilingFbm(u, v, 32, 2, seed);
}

// ---- leaves -------------------------------------------------------------------------------------
struct Leaf {
  glm::vec2 base, axis;  // stem point and unit direction to the tip
  float length, width;
  glm::vec3 colour;
};

}  // namespace

Image8 makeCheckerTexture(int size, int cells, glm::u8vec3 a, glm::u8vec3 b) {
  Image8 image = blank(size, 3);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const bool first = ((x * cells / size) + (y * cells / size)) % 2 == 0;
      const glm::u8vec3 c = first ? a : b;
      std::uint8_t* p = image.at(x, y);
      p[0] = c.x;
      p[1] = c.y;
      p[2] = c.z;
    }
  return image;
}

Image8 makeBricksTexture(int size, std::uint64_t seed) {
  Image8 image = blank(size, 3);
  const glm::vec3 mortar{0.72f, 0.70f, 0.66f};
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const float u = (float(x) + 0.5f) / float(size), v = (float(y) + 0.5f) / float(size);
      const BrickSample s = brickAt(u, v);
      SplitMix64 brick(s.id ^ seed);
      const glm::vec3 base{0.55f + brick.uniform(-0.08f, 0.08f), 0.22f + brick.uniform(-0.05f, 0.05f),
                           0.15f + brick.uniform(-0.04f, 0.04f)};
      const float grain = 0.85f + 0.3f * tilingFbm(u, v, 32, 3, seed);
      setRgb(image, x, y, (mortar + (base - mortar) * s.height) * grain);
    }
  return image;
}

Image8 makeBricksNormalTexture(int size, std::uint64_t seed) {
  Image8 image = blank(size, 3);
  // Heights in texels of relief: the bevel rises over a few texels, so slopes near 1 look right.
  const float strength = float(size) / 48.0f;
  std::vector<float> h(std::size_t(size) * size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      h[std::size_t(y) * size + x] =
          strength * brickSurface((float(x) + 0.5f) / float(size), (float(y) + 0.5f) / float(size), seed);
  auto at = [&](int x, int y) { return h[std::size_t(wrap(y, size)) * size + std::size_t(wrap(x, size))]; };
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const float dhdu = 0.5f * (at(x + 1, y) - at(x - 1, y));
      const float dhdv = 0.5f * (at(x, y + 1) - at(x, y - 1));  // +v is down the image
      const glm::vec3 n = glm::normalize(glm::vec3(-dhdu, -dhdv, 1.0f));
      setRgb(image, x, y, n * 0.5f + 0.5f);
    }
  return image;
}

Image8 makeLeavesTexture(int size, std::uint64_t seed) {
  Image8 image = blank(size, 4);
  SplitMix64 rng(seed);
  std::vector<Leaf> leaves;
  const int count = 48;
  for (int i = 0; i < count; ++i) {
    Leaf leaf;
    glm::vec2 d;
    do d = {rng.uniform(-1.0f, 1.0f), rng.uniform(-1.0f, 1.0f)};
    while (glm::dot(d, d) > 1.0f || glm::dot(d, d) < 0.05f);
    leaf.axis = d / std::sqrt(glm::dot(d, d));
    leaf.length = rng.uniform(0.16f, 0.26f);
    leaf.width = leaf.length * rng.uniform(0.22f, 0.32f);
    // Stem and tip both inside the card, so no leaf is cut at the border.
    glm::vec2 tip;
    do {
      leaf.base = {rng.uniform(0.04f, 0.96f), rng.uniform(0.04f, 0.96f)};
      tip = leaf.base + leaf.axis * leaf.length;
    } while (tip.x < 0.04f || tip.x > 0.96f || tip.y < 0.04f || tip.y > 0.96f);
    leaf.colour = {rng.uniform(0.12f, 0.25f), rng.uniform(0.35f, 0.55f), rng.uniform(0.08f, 0.15f)};
    leaves.push_back(leaf);
  }
  const glm::vec3 background{0.18f, 0.42f, 0.1f};
  // 4x4 supersampling: alpha is the leaf coverage of the texel. Each leaf is first rasterised
  // over its own bounding box into a buffer of which leaf is on top of each sample (the last
  // drawn wins), so the cost grows with leaf area rather than with leaves x texels.
  constexpr int kSub = 4;
  const int samples = size * kSub;
  auto samplePoint = [&](int x, int y, int sx, int sy) {
    return glm::vec2{(float(x) + (float(sx) + 0.5f) / kSub) / float(size),
                     (float(y) + (float(sy) + 0.5f) / kSub) / float(size)};
  };
  struct Hit {
    float across, halfWidth;
  };
  auto inside = [&](const Leaf& leaf, const glm::vec2& p, Hit& hit) {
    const glm::vec2 d = p - leaf.base;
    const float t = glm::dot(d, leaf.axis) / leaf.length;  // 0 at the stem, 1 at the tip
    if (t < 0.0f || t > 1.0f) return false;
    hit.across = std::abs(d.x * leaf.axis.y - d.y * leaf.axis.x);
    hit.halfWidth = leaf.width * 4.0f * t * (1.0f - t) * (1.0f - 0.3f * t);
    return hit.across <= hit.halfWidth;
  };
  std::vector<std::uint8_t> top(std::size_t(samples) * samples, 0xFF);
  for (int i = 0; i < count; ++i) {
    const Leaf& leaf = leaves[i];
    const glm::vec2 tip = leaf.base + leaf.axis * leaf.length;
    const glm::vec2 lo = glm::min(leaf.base, tip) - leaf.width, hi = glm::max(leaf.base, tip) + leaf.width;
    const int x0 = std::max(0, int(lo.x * float(samples)) - 2),
              x1 = std::min(samples - 1, int(hi.x * float(samples)) + 2);
    const int y0 = std::max(0, int(lo.y * float(samples)) - 2),
              y1 = std::min(samples - 1, int(hi.y * float(samples)) + 2);
    Hit hit{};
    for (int Y = y0; Y <= y1; ++Y)
      for (int X = x0; X <= x1; ++X)
        if (inside(leaf, samplePoint(X / kSub, Y / kSub, X % kSub, Y % kSub), hit))
          top[std::size_t(Y) * samples + X] = std::uint8_t(i);
  }
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      int covered = 0;
      glm::vec3 colour(0.0f);
      for (int sy = 0; sy < kSub; ++sy)
        for (int sx = 0; sx < kSub; ++sx) {
          const std::uint8_t i = top[std::size_t(y * kSub + sy) * samples + std::size_t(x * kSub + sx)];
          if (i == 0xFF) continue;
          Hit hit{};
          inside(leaves[i], samplePoint(x, y, sx, sy), hit);
          const float vein = hit.across < 0.004f ? 0.7f : 1.0f;  // the midrib, darker
          colour += leaves[i].colour * vein * (0.8f + 0.4f * (hit.across / std::max(hit.halfWidth, 1e-6f)));
          ++covered;
        }
      const glm::vec3 c = covered ? colour / float(covered) : background;
      setRgb(image, x, y, c);
      image.at(x, y)[3] = std::uint8_t((covered * 255 + kSub * kSub / 2) / (kSub * kSub));
    }
  return image;
}

Image8 makeGroundTexture(int size, std::uint64_t seed) {
  Image8 image = blank(size, 3);
  const glm::vec3 grass{0.24f, 0.42f, 0.12f}, dryGrass{0.45f, 0.5f, 0.2f}, dirt{0.42f, 0.3f, 0.18f};
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const float u = (float(x) + 0.5f) / float(size), v = (float(y) + 0.5f) / float(size);
      const float patches = tilingFbm(u, v, 4, 4, seed);
      const float dryness = tilingFbm(u, v, 8, 2, seed + 1);
      const float speckle = tilingNoise(u * float(size) * 0.5f, v * float(size) * 0.5f, size / 2, seed + 2);
      const glm::vec3 green = grass + (dryGrass - grass) * dryness;
      const float dirtAmount = smoothstep(0.45f, 0.6f, patches);
      setRgb(image, x, y, (green + (dirt - green) * dirtAmount) * (0.8f + 0.4f * speckle));
    }
  return image;
}

Image8 makeTextTexture(int size, std::uint64_t seed) {
  Image8 image = blank(size, 3, 242);  // paper
  // Glyphs are 5x7 dots in 6x10 cells; lines of words with ragged right edges.
  const int cellW = 6, cellH = 10, margin = 12;
  const int columns = (size - 2 * margin) / cellW, rows = (size - 2 * margin) / cellH;
  SplitMix64 rng(seed);
  for (int row = 0; row < rows; ++row) {
    int col = 0;
    const int lineEnd = columns - rng.below(8);
    while (col < lineEnd) {
      const int word = 2 + rng.below(8);
      for (int k = 0; k < word && col < lineEnd; ++k, ++col) {
        const std::uint64_t bits = rng.next();
        for (int gy = 0; gy < 7; ++gy)
          for (int gx = 0; gx < 5; ++gx) {
            // Strokes: a dot is set by its bit, and rows keep a glyph-like density of about 45%.
            if (((bits >> (gy * 5 + gx)) & 1u) == 0 || ((bits >> (35 + gy * 3 + gx % 3)) & 1u) == 0) continue;
            std::uint8_t* p = image.at(margin + col * cellW + gx, margin + row * cellH + gy + 1);
            p[0] = 20;
            p[1] = 22;
            p[2] = 30;
          }
      }
      ++col;  // the space between words
    }
  }
  return image;
}

Image8 makeFenceTexture(int size) {
  Image8 image = blank(size, 4);
  const glm::vec3 wood{0.55f, 0.42f, 0.28f};
  const int pickets = 4;
  const float picketWidth = 0.16f;  // of the texture, per picket
  const float railTop[2] = {0.35f, 0.75f}, railHeight = 0.07f;
  constexpr int kSub = 4;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      int covered = 0;
      for (int sy = 0; sy < kSub; ++sy)
        for (int sx = 0; sx < kSub; ++sx) {
          const float u = (float(x) + (float(sx) + 0.5f) / kSub) / float(size);
          const float v = (float(y) + (float(sy) + 0.5f) / kSub) / float(size);
          const float slot = u * pickets, within = slot - std::floor(slot) - 0.5f;  // [-0.5, 0.5)
          const float halfWidth = 0.5f * picketWidth * pickets;
          // A picket is a strip with a pointed top: its half width grows from 0 at v = 0.02.
          const bool picket =
              std::abs(within) < halfWidth && v > 0.02f && std::abs(within) < (v - 0.02f) * 1.6f && v < 0.98f;
          const bool rail =
              (v > railTop[0] && v < railTop[0] + railHeight) || (v > railTop[1] && v < railTop[1] + railHeight);
          covered += picket || rail;
        }
      const float grain = 0.85f + 0.3f * tilingFbm((float(x) + 0.5f) / float(size) * 0.25f,
                                                   (float(y) + 0.5f) / float(size), 16, 3, 0xFE4CE);
      setRgb(image, x, y, wood * grain);
      image.at(x, y)[3] = std::uint8_t((covered * 255 + kSub * kSub / 2) / (kSub * kSub));
    }
  return image;
}

std::vector<std::pair<std::string, Image8>> generateCourseTextures() {
  std::vector<std::pair<std::string, Image8>> out;
  out.emplace_back("checker.png", makeCheckerTexture(256, 8, {230, 230, 230}, {60, 60, 70}));
  out.emplace_back("checker_fine.png", makeCheckerTexture(512, 64, {255, 255, 255}, {0, 0, 0}));
  out.emplace_back("bricks.png", makeBricksTexture(512, 17));
  out.emplace_back("bricks_normal.png", makeBricksNormalTexture(512, 17));
  out.emplace_back("leaves.png", makeLeavesTexture(512, 23));
  out.emplace_back("ground.png", makeGroundTexture(256, 31));
  out.emplace_back("text.png", makeTextTexture(512, 41));
  out.emplace_back("fence.png", makeFenceTexture(256));
  return out;
}

}  // namespace shadowlab
