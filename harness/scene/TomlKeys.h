#pragma once
// Strict TOML files (case files, expectations): a parse error or a key a table does not
// know is an error at its line and column, with the closest known key suggested ("did you
// mean 'tolerance'?"), so a typo is never silently ignored.
#include <initializer_list>
#include <string>
#include <string_view>

#include <toml++/toml.h>

#include "core/Error.h"

namespace shaderbed {

// The parsed file; a syntax error is an Error at its line and column in `stage`.
Result<toml::table> parse_toml_file(const std::string& path, ErrorStage stage);

// `where` names the table in the message ("the case", "[tolerance]", ...).
Result<void> check_keys(const std::string& path, const toml::table& table, std::initializer_list<std::string_view> known,
                        const std::string& where, ErrorStage stage = ErrorStage::case_file);

// The known key nearest to `key` by edit distance, or "" when none is close.
std::string closest_key(std::string_view key, std::initializer_list<std::string_view> known);

}  // namespace shaderbed
