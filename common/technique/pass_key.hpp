#pragma once
// Everything a shadow pass's result depends on, as bytes: when this frame's key equals the one the
// map was rendered with, nothing invalidated the map and its pass can be skipped (the map is
// reused; "maps reused" in the header). Exact: compared byte for byte, not hashed.
#include <cstdint>
#include <cstring>
#include <span>
#include <type_traits>
#include <vector>

namespace shadowlab::tech {

class PassKey {
 public:
  template <class T>
  PassKey& operator<<(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>, "a pass key holds plain values");
    const auto* p = reinterpret_cast<const std::uint8_t*>(&value);
    bytes_.insert(bytes_.end(), p, p + sizeof(T));
    return *this;
  }
  PassKey& operator<<(std::span<const char> flags) {
    *this << flags.size();
    bytes_.insert(bytes_.end(), flags.begin(), flags.end());
    return *this;
  }
  bool operator==(const PassKey& other) const = default;
  bool empty() const { return bytes_.empty(); }
  void clear() { bytes_.clear(); }

 private:
  std::vector<std::uint8_t> bytes_;
};

}  // namespace shadowlab::tech
