#pragma once
// How the cascade math words its errors: std::invalid_argument naming the parameter, with values
// printed the way std::ostream prints them. One copy for splits, frustum and light fit.
#include <sstream>
#include <stdexcept>
#include <string>

namespace st::csm {

template <typename T>
std::string str(T v) {
    std::ostringstream out;
    out << v;
    return out.str();
}

[[noreturn]] inline void fail(const std::string& message) { throw std::invalid_argument(message); }

}  // namespace st::csm
