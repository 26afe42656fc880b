#include "app/version.h"

#include "st_version.h"  // generated at build time by cmake/version_header.cmake

namespace st::app {

std::string productVersion() { return ST_VERSION; }
std::string buildCommit() { return ST_GIT_COMMIT; }

std::string versionText() { return "shadowtune " ST_VERSION " (commit " ST_GIT_COMMIT ")"; }

}  // namespace st::app
