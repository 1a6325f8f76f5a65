#pragma once
// A value or an error, for functions whose failure is an ordinary outcome (bad input files).

#include <cassert>
#include <utility>
#include <variant>

namespace fosssim {

template <typename T, typename E>
class Expected {
 public:
  Expected(T value) : content_(std::in_place_index<0>, std::move(value)) {}  // NOLINT
  Expected(E error) : content_(std::in_place_index<1>, std::move(error)) {}  // NOLINT

  bool has_value() const { return content_.index() == 0; }
  explicit operator bool() const { return has_value(); }

  T& value() & {
    assert(has_value());
    return std::get<0>(content_);
  }
  const T& value() const& {
    assert(has_value());
    return std::get<0>(content_);
  }
  T&& value() && {
    assert(has_value());
    return std::get<0>(std::move(content_));
  }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }
  T& operator*() & { return value(); }

  const E& error() const {
    assert(!has_value());
    return std::get<1>(content_);
  }

 private:
  std::variant<T, E> content_;
};

}  // namespace fosssim
