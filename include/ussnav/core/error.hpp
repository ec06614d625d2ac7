#pragma once
// One exception type for bad input from outside (files, configs, replies). Its message is a
// single line naming the file, the field and what was expected; the CLI prints it and exits 2.

#include <stdexcept>
#include <string>

namespace ussnav {

class InputError : public std::runtime_error {
 public:
  InputError(const std::string& file, const std::string& field, const std::string& what);
  const std::string& file() const { return file_; }
  const std::string& field() const { return field_; }

 private:
  std::string file_, field_;
};

}  // namespace ussnav
