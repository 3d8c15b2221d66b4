#pragma once
// Rows of an image (or any index range) over threads: each worker takes the next row until none
// is left, so uneven rows balance themselves. fn(y) must only touch row y's data. The first
// exception a row throws stops the others taking rows and is rethrown here, after every thread
// has joined (a worker's exception would otherwise end the program).
#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace shadowlab {

// threads <= 0: std::thread::hardware_concurrency().
template <class RowFn>
void parallelRows(int height, int threads, RowFn&& fn) {
  int count = threads > 0 ? threads : int(std::max(1u, std::thread::hardware_concurrency()));
  count = std::max(1, std::min(count, height));
  std::atomic<int> next{0};
  std::exception_ptr failure;
  std::mutex failureLock;
  auto worker = [&] {
    for (int y; (y = next.fetch_add(1)) < height;) {
      try {
        fn(y);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(failureLock);
        if (!failure) failure = std::current_exception();
        next.store(height);  // no more rows for anyone
      }
    }
  };
  if (count == 1) {
    worker();
  } else {
    std::vector<std::thread> pool;
    for (int i = 1; i < count; ++i) pool.emplace_back(worker);
    worker();
    for (auto& t : pool) t.join();
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace shadowlab
