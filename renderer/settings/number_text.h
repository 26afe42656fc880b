#pragma once
// Numbers as short, exact text: for error messages and for tidy preset JSON.
#include <string>

namespace st {

// Shortest text that reads back to exactly `value`: 0.1, 12, 0.0001, 1000000, 1e+20, inf, nan.
std::string formatNumber(double value);
std::string formatFloat(float value);

// The double whose shortest text equals the float's (0.1f -> 0.1, not 0.10000000149011612), so
// presets show what was typed and still read back to exactly the same float.
double tidyFloat(float value);

}  // namespace st
