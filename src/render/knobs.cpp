#include "knobs.hpp"

#include <sstream>

#include "../util/error.hpp"

namespace lucent::render {

std::map<std::string, std::string> parseKnobList(const std::string& text) {
  std::map<std::string, std::string> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    const auto eq = item.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError("knob '" + item + "' must be written name=value, e.g. spacing=0.1");
    out[item.substr(0, eq)] = item.substr(eq + 1);
  }
  return out;
}

}  // namespace lucent::render
