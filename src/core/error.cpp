#include "ussnav/core/error.hpp"

namespace ussnav {

static std::string compose(const std::string& file, const std::string& field,
                           const std::string& what) {
  std::string s = file.empty() ? std::string("<input>") : file;
  if (!field.empty()) s += ": " + field;
  return s + ": " + what;
}

InputError::InputError(const std::string& file, const std::string& field, const std::string& what)
    : std::runtime_error(compose(file, field, what)), file_(file), field_(field) {}

}  // namespace ussnav
