#include "transport/mixture/table_messages.hpp"

#include <cstdio>
#include <stdexcept>

namespace gkt::detail {

std::string short_number(double x, int digits) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, x);
  return buffer;
}

void refuse_state(const char* name, const char* range, double value, double temperature) {
  if (*range == '\0')
    throw std::invalid_argument(std::string(name) + ": the coefficients at n = " + short_number(value) +
                                ", T = " + short_number(temperature) + " over- or underflow a double");
  throw std::invalid_argument(std::string(name) + ": must be " + range + ", got " + short_number(value));
}

}  // namespace gkt::detail
