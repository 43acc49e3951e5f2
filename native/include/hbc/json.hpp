#pragma once
// hbc's one JSON writer, for the CLI, the WebAssembly binding and the library's reports
// (hbc/report.hpp): nlohmann's ordered_json (keys in insertion order, so output is stable),
// escaped correctly, non-finite numbers written as null.
#include <nlohmann/json.hpp>
#include <string>

namespace hbc {

using Json = nlohmann::ordered_json;

// Two-space indented text with a final newline.
// File names that are not UTF-8 are written with U+FFFD in place of the bad bytes.
inline std::string json_text(const Json& j) { return j.dump(2, ' ', false, Json::error_handler_t::replace) + "\n"; }

}  // namespace hbc
