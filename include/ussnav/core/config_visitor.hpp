#pragma once
// Declare-once configuration (after Hydra's declare_config). Each config struct has
//   template <class V> void visit(V& v) { v.field("key", member, lo, hi, "unit/doc"); ... }
// and nested structs are visited with v.section("key", sub). The YAML loader, the printer and
// the validator are all visitors, so a key is written in exactly one place.

#include <string>
#include <vector>

namespace ussnav {

// A string field restricted to a set of choices.
struct Choice {
  std::string* value;
  std::vector<std::string> options;
};

}  // namespace ussnav
