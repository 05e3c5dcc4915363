// Small dense ids and readable names for component/resource types, without RTTI.
// typeId<const T>() == typeId<T>(): constness is an access mode, not another type.
#pragma once

#include <atomic>
#include <cstdint>
#include <string_view>
#include <type_traits>

namespace qlight::ecs {

using TypeId = uint32_t;

namespace detail {
inline std::atomic<TypeId> nextTypeId{0};

template <class T>
TypeId typeIdOf() {
  static const TypeId id = nextTypeId.fetch_add(1, std::memory_order_relaxed);
  return id;
}
}  // namespace detail

// Ids are handed out in first-use order, so they index vectors of per-type pools.
template <class T>
TypeId typeId() {
  return detail::typeIdOf<std::remove_cvref_t<T>>();
}

// "Position" or "game::Position" from the compiler's function signature (GCC and Clang).
template <class T>
constexpr std::string_view typeName() {
  std::string_view sig = __PRETTY_FUNCTION__;
  const std::string_view key = "T = ";
  const size_t begin = sig.find(key);
  if (begin == std::string_view::npos) return "unknown type";
  sig.remove_prefix(begin + key.size());
  const size_t end = sig.find_first_of(";]");
  return end == std::string_view::npos ? sig : sig.substr(0, end);
}

}  // namespace qlight::ecs
