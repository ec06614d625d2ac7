#pragma once
// The message of the InputError that `f` throws, or "" when it throws none (other exceptions
// propagate): for tests that check a bad input names its file and field.

#include <functional>
#include <string>

#include "ussnav/core/error.hpp"

namespace ussnav::test {

inline std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace ussnav::test
