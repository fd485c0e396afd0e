#pragma once
/// @file error.hpp
/// @brief The one exception type the CLI and adapters throw for bad input: its message names the file or
/// option, the problem and the fix, and the CLI turns it into one line on stderr and exit code 2.
#include <stdexcept>
#include <string>

namespace lucent {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace lucent
