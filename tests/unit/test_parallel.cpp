// core/parallel.hpp: the rows the CPU references (ground truth, lesson 06's sampler) share out.
#include <doctest/doctest.h>

#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/parallel.hpp"

using namespace shadowlab;

TEST_CASE("parallelRows: every row exactly once, for any thread count") {
  for (int height : {0, 1, 7, 100}) {
    for (int threads : {0, 1, 2, 5, 200}) {
      std::vector<std::atomic<int>> visits(static_cast<std::size_t>(height));
      parallelRows(height, threads, [&](int y) { ++visits[std::size_t(y)]; });
      int wrong = 0;
      for (const auto& v : visits) wrong += v.load() != 1;
      CHECK_MESSAGE(wrong == 0, "height " << height << ", threads " << threads);
    }
  }
}

TEST_CASE("parallelRows: a row's exception reaches the caller after every thread has joined") {
  for (int threads : {1, 2, 4}) {
    std::atomic<int> done{0};
    auto run = [&] {
      parallelRows(64, threads, [&](int y) {
        if (y == 17) throw std::runtime_error("row 17 failed");
        ++done;
      });
    };
    CHECK_THROWS_WITH_AS(run(), "row 17 failed", std::runtime_error);
    CHECK(done.load() < 64);  // row 17 never counts
  }
}
