#pragma once
// JUnit XML of a check run, as CI servers read it: one test suite, a test case per preset
// (its image and status) and per checked figure, the numbers in each failure's message, and
// the diff image attached as [[ATTACHMENT|path]] in the preset's system-out (Jenkins'
// attachments plugin; Flutter #117051). tests/check/junit.xsd is the schema it is checked
// against. No GL.
#include "check/check_run.h"

#include <filesystem>
#include <string>
#include <vector>

namespace st::check {

// `reportDir`: where the images named by results' *Png are (absolute paths go into the
// attachments); empty when no report was written.
std::string junitXml(const std::string& suiteName, const std::vector<PresetResult>& results,
                     const std::filesystem::path& reportDir);

}  // namespace st::check
