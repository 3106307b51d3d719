#pragma once
// Text helpers the XML and HTML writers share (internal to harness/report).
#include <string>
#include <string_view>

namespace shaderbed::markup {

// Valid UTF-8 that XML 1.0 accepts: invalid byte sequences become U+FFFD, and control
// characters other than tab, newline and carriage return become "\xNN".
std::string clean_text(std::string_view s);
// clean_text, then & < > " ' escaped; in attributes newlines and tabs are kept as &#10; / &#9;.
std::string escape(std::string_view s, bool attribute = false);

std::string base64(std::string_view bytes);

// A JSON string literal (quotes included) that is safe inside an HTML <script> element:
// besides JSON's own escapes, "</" is written "<\/" and "<!" "\u003c!", so no "</script"
// or "<!--" can occur. `s` must be valid UTF-8 (clean_text's output is).
std::string script_json_string(std::string_view s);

// "1.23e-04", "inf", "nan", "-" for an unmeasured value.
std::string sci(double v);

}  // namespace shaderbed::markup
