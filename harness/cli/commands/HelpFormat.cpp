#include "cli/commands/HelpFormat.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace shaderbed {
namespace {

constexpr size_t kNameColumn = 30;   // CLI11's own

// `text` with its lines folded at spaces to `width` columns.
std::string wrapped(const std::string& text, size_t width) {
  width = std::max<size_t>(width, 20);
  std::string out;
  for (size_t at = 0; at <= text.size();) {
    const size_t end = std::min(text.find('\n', at), text.size());
    std::string line = text.substr(at, end - at);
    while (line.size() > width) {
      size_t cut = line.rfind(' ', width);
      if (cut == std::string::npos || cut == 0) cut = std::min(line.find(' ', width), line.size());
      if (cut >= line.size()) break;   // one word wider than the screen: left whole
      out += line.substr(0, cut) + "\n";
      line = line.substr(cut + 1);
    }
    out += line;
    if (end < text.size()) out += "\n";
    at = end + 1;
  }
  return out;
}

class WrappingFormatter : public CLI::Formatter {
 public:
  explicit WrappingFormatter(size_t width) : width_(width) {}

  std::string make_option_desc(const CLI::Option* opt) const override {
    return wrapped(opt->get_description(), width_ - kNameColumn);
  }
  std::string make_subcommand(const CLI::App* sub) const override {
    std::string out = "  " + sub->get_display_name(true);
    out.resize(std::max(out.size() + 1, kNameColumn), ' ');
    if (out.size() > kNameColumn) out = out.substr(0, out.size() - 1) + "\n" + std::string(kNameColumn, ' ');
    const std::string desc = wrapped(sub->get_description(), width_ - kNameColumn);
    for (char c : desc) out += c == '\n' ? "\n" + std::string(kNameColumn, ' ') : std::string(1, c);
    return out + "\n";
  }
  std::string make_description(const CLI::App* app) const override {
    return wrapped(CLI::Formatter::make_description(app), width_);
  }
  std::string make_footer(const CLI::App* app) const override {
    return wrapped(CLI::Formatter::make_footer(app), width_);
  }

 private:
  size_t width_;
};

bool ends_with_any(const std::string& name, std::initializer_list<const char*> ends) {
  return std::any_of(ends.begin(), ends.end(), [&](const char* e) { return name.ends_with(e); });
}

bool generic(const std::string& type) { return type == "TEXT" || type == "INT" || type == "UINT" || type == "FLOAT"; }

// What an option's value is, from its name and CLI11's type, where CLI11 says only TEXT or
// INT. `choice`: a validator lists the allowed values after it.
std::string placeholder(const CLI::Option& o, const std::string& type, bool choice) {
  const std::string name = o.get_name(false, false);
  if (choice) return "WORD";
  if (ends_with_any(name, {"-dir", "--out", "--html", "--save-images", "--against"})) return "DIR";
  if (ends_with_any(name, {"--json", "--junit", "--csv", "--expectations", "--chart", "--baseline", "--from", "file"}))
    return "FILE";
  if (o.get_expected_max() > 1 && type == "TEXT") return "LIST";
  if (type == "INT" || type == "UINT") return "N";
  if (type == "FLOAT") return name.ends_with("timeout") ? "SECONDS" : "X";
  return "VALUE";
}

void format_app(CLI::App& app, const std::shared_ptr<WrappingFormatter>& formatter) {
  app.formatter(formatter);
  for (CLI::Option* o : app.get_options()) {
    if (o->get_type_size() == 0 || o->get_positional()) continue;
    // CLI11's type name, then ":" and a validator's description ("TEXT:{a,b}"): only the
    // bare type name is replaced.
    const std::string type = o->get_type_name();
    const std::string head = type.substr(0, type.find(':'));
    if (generic(head)) o->type_name(placeholder(*o, head, type.find(":{") != std::string::npos));
    // A default under the build machine's source tree means nothing to a reader.
    const std::string def = o->get_default_str();
    if (def.starts_with("/") && def.ends_with("/shaders/cases")) o->default_str("<root>/shaders/cases");
  }
  for (CLI::App* sub : app.get_subcommands(std::function<bool(CLI::App*)>{})) format_app(*sub, formatter);
}

}  // namespace

size_t help_width() {
  if (const char* columns = std::getenv("COLUMNS")) {
    size_t width = 0;
    const std::string_view text(columns);
    if (std::from_chars(text.data(), text.data() + text.size(), width).ec == std::errc{} && width >= 40) return width;
  }
  winsize ws{};
  if (ioctl(STDOUT_FILENO, TIOCGWINSZ, &ws) == 0 && ws.ws_col >= 40) return ws.ws_col;
  return 100;
}

void format_help(CLI::App& app) {
  format_app(app, std::make_shared<WrappingFormatter>(help_width()));
}

}  // namespace shaderbed
