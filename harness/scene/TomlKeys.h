#pragma once
// Strict TOML tables: a key a table does not know is an error at its line and column,
// with the closest known key suggested ("did you mean 'tolerance'?"), so a typo in a case
// file is never silently ignored.
#include <initializer_list>
#include <string>
#include <string_view>

#include <toml++/toml.h>

#include "core/Error.h"

namespace shaderbed {

// `where` names the table in the message ("the case", "[tolerance]", ...).
Result<void> check_keys(const std::string& path, const toml::table& table, std::initializer_list<std::string_view> known,
                        const std::string& where);

// The known key nearest to `key` by edit distance, or "" when none is close.
std::string closest_key(std::string_view key, std::initializer_list<std::string_view> known);

}  // namespace shaderbed
