#pragma once
// KHR_debug output: every message is printed; medium and high severity ones are counted so tests
// can fail on them ("GL errors are bugs").
#include <string>
#include <vector>

namespace st::gpu {

void enableDebugOutput();                    // needs a current (debug) context
int seriousDebugMessageCount();              // medium + high severity since start
std::vector<std::string> seriousDebugMessages();

}  // namespace st::gpu
