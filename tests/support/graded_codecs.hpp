#pragma once
// How the answers of exercise functions that return more than plain bytes are recorded and replayed
// (common/grading/answers.hpp): an image, a merge grid. Plain structs and glm types need nothing.
#include <cstdint>
#include <string>

#include "algorithms/hybrid_map.hpp"
#include "core/image.hpp"
#include "grading/answers.hpp"

namespace shadowlab {

inline void encodeAnswer(std::string& out, const ImageF& image) {
  grading::encodeAnswer(out, std::int32_t(image.width));
  grading::encodeAnswer(out, std::int32_t(image.height));
  grading::encodeAnswer(out, std::int32_t(image.channels));
  grading::encodeAnswer(out, image.data);
}
inline void decodeAnswer(grading::AnswerReader& in, ImageF& image) {
  std::int32_t w = 0, h = 0, c = 0;
  grading::decodeAnswer(in, w);
  grading::decodeAnswer(in, h);
  grading::decodeAnswer(in, c);
  image.width = w, image.height = h, image.channels = c;
  grading::decodeAnswer(in, image.data);
}

namespace hybrid {
inline void encodeAnswer(std::string& out, const MergeGrid& grid) {
  grading::encodeAnswer(out, std::int32_t(grid.size));
  grading::encodeAnswer(out, grid.value);
}
inline void decodeAnswer(grading::AnswerReader& in, MergeGrid& grid) {
  std::int32_t size = 0;
  grading::decodeAnswer(in, size);
  grid.size = size;
  grading::decodeAnswer(in, grid.value);
}
}  // namespace hybrid

}  // namespace shadowlab
