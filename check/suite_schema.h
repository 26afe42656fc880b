#pragma once
// The check suite's JSON Schema (draft 2020-12), its figure names taken from the figures table.
// schema/suite.schema.json holds a copy; a test keeps it from going stale. No GL.
#include <string>

namespace st::check {

std::string suiteJsonSchemaText();  // 2-space indent, final newline

}  // namespace st::check
