#pragma once
// The checks of the commands' numeric options. CLI11's own (PositiveNumber, Range) let NaN through
// (every comparison with NaN is false) and print their bounds as 17-digit doubles; these refuse NaN
// and infinity and name the allowed range in plain numbers. A failed check is a usage error: main
// prints its one line and exits 2 before any command has run, so nothing is written.
#include <CLI/CLI.hpp>

#include <string>

namespace st::app {

CLI::Validator positiveNumber();              // finite, > 0
CLI::Validator nonNegativeNumber();           // finite, >= 0
CLI::Validator numberIn(double lo, double hi);  // finite, lo..hi

}  // namespace st::app
