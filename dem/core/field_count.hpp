// The number of fields of a plain struct (an aggregate), counted at compile time by how many
// initialisers it takes: what lets a struct whose fields are listed once more elsewhere (the
// State's, for a checkpoint: dem/step/state.hpp) fail a check when a field is added to it and not to
// the list. Boost.PFR does the same; Debian 12's Boost (1.74) predates it.
#pragma once

#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

namespace icedem {
namespace field_count_detail {

// a visitor that does nothing with a field
struct IgnoreField {
  template <typename Field>
  void operator()(const char*, Field&) const {}
};

// converts to the type of any field
struct AnyField {
  template <typename T>
  operator T() const;  // declared only: used in unevaluated contexts
};

template <typename T, typename... Fields>
constexpr auto takes(int) -> decltype(T{std::declval<Fields>()...}, bool()) {
  return true;
}
template <typename T, typename... Fields>
constexpr bool takes(...) {
  return false;
}

}  // namespace field_count_detail

/// The number of fields of the aggregate T.
template <typename T, typename... Fields>
constexpr std::size_t field_count() {
  using field_count_detail::AnyField;
  if constexpr (field_count_detail::takes<T, Fields..., AnyField>(0))
    return field_count<T, Fields..., AnyField>();
  else
    return sizeof...(Fields);
}

/// Whether T is a std::vector (a field of records).
template <typename T>
struct IsVector : std::false_type {};
template <typename T>
struct IsVector<std::vector<T>> : std::true_type {};

/// Whether T lists its fields by a visit_fields(T&, visit) (the State's values and their parts).
template <typename T, typename = void>
struct HasFields : std::false_type {};
template <typename T>
struct HasFields<T, std::void_t<decltype(visit_fields(std::declval<T&>(), field_count_detail::IgnoreField{}))>>
    : std::true_type {};

/// The number of fields `visit_fields(T&, visit)` visits (the list a struct's fields are written by).
template <typename T>
std::size_t visited_count() {
  T value{};
  std::size_t n = 0;
  visit_fields(value, [&n](const char*, auto&) { ++n; });
  return n;
}

}  // namespace icedem
