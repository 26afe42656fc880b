#pragma once
// `shadowtune --version`: the project version and the git commit the binary was built from.
#include <string>

namespace st::app {

// "shadowtune 0.1 (commit 0123456789ab)"; the commit is "unknown" for a build outside a git
// checkout and ends in "-dirty" when the tree had uncommitted changes.
std::string versionText();
std::string productVersion();  // "0.1"
std::string buildCommit();     // "0123456789ab", "unknown" or "...-dirty"

}  // namespace st::app
