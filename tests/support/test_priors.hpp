#pragma once
// The repository's commonsense priors with the WordNet text encoder, loaded once per test binary.

#include <memory>

#include "ussnav/reasoning/priors.hpp"

namespace ussnav::test {

inline std::shared_ptr<const CommonsensePriors> priors() {
  static const auto p = CommonsensePriors::load(CommonsensePriors::defaultDir(), makeTextEncoder("wordnet"));
  return p;
}

}  // namespace ussnav::test
