#pragma once
// The sweep file's JSON Schema (draft 2020-12), generated from the field table: each axis's
// values take the schema of its field. schema/sweep.schema.json holds a copy; a test keeps it fresh.
#include <string>

namespace st::sweep {

std::string sweepJsonSchemaText();  // 2-space indent and a final newline

}  // namespace st::sweep
