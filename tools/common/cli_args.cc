#include "common/cli_args.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <utility>

#include "common/version.h"

namespace hullpack {
namespace {

constexpr size_t kHelpColumn = 28;  // where the help text of an option starts

std::vector<std::string> SplitNames(const std::string& names) {
  std::vector<std::string> out;
  std::string name;
  for (char c : names + ",") {
    if (c == ',') {
      if (!name.empty()) out.push_back(name);
      name.clear();
    } else if (c != ' ') {
      name.push_back(c);
    }
  }
  return out;
}

std::string Join(const std::vector<std::string>& parts, const std::string& separator) {
  std::string out;
  for (const std::string& p : parts) out += (out.empty() ? "" : separator) + p;
  return out;
}

// "  -o, --output FILE" padded to the help column (or on a line of its own when too long), then
// the help text with its continuation lines indented to that column.
std::string HelpEntry(const std::string& names, const std::string& help) {
  std::string out = "  " + names;
  const std::string indent(kHelpColumn, ' ');
  if (out.size() + 2 > kHelpColumn) {
    out += "\n" + indent;
  } else {
    out += std::string(kHelpColumn - out.size(), ' ');
  }
  for (char c : help) {
    out.push_back(c);
    if (c == '\n') out += indent;
  }
  return out + "\n";
}

}  // namespace

CliArgs::CliArgs(std::string program, std::string synopsis, std::string summary)
    : program_(std::move(program)), synopsis_(std::move(synopsis)), summary_(std::move(summary)) {}

CliArgs& CliArgs::Add(Option option) {
  options_.push_back(std::move(option));
  return *this;
}

CliArgs& CliArgs::Flag(const std::string& names, bool* out, const std::string& help) {
  return Action(names, help, [out]() { *out = true; });
}

CliArgs& CliArgs::Action(const std::string& names, const std::string& help,
                         std::function<void()> apply) {
  Option o;
  o.names = SplitNames(names);
  o.help = help;
  o.apply = [apply](const std::string&) {
    apply();
    return std::string();
  };
  return Add(std::move(o));
}

CliArgs& CliArgs::Value(const std::string& names, const std::string& value_name,
                        const std::string& help, Apply apply) {
  Option o;
  o.names = SplitNames(names);
  o.value_name = value_name.empty() ? "VALUE" : value_name;
  o.help = help;
  o.apply = std::move(apply);
  return Add(std::move(o));
}

CliArgs& CliArgs::String(const std::string& names, const std::string& value_name, std::string* out,
                         const std::string& help) {
  return Value(names, value_name, help, [out](const std::string& v) {
    *out = v;
    return std::string();
  });
}

CliArgs& CliArgs::Double(const std::string& names, const std::string& value_name, double lo,
                         double hi, double* out, const std::string& help) {
  return Value(names, value_name, help,
               [lo, hi, out](const std::string& v) { return ParseNumber(v, lo, hi, out); });
}

CliArgs& CliArgs::Choice(const std::string& names, const std::vector<std::string>& choices,
                         std::string* out, const std::string& help) {
  return Value(names, Join(choices, "|"), help, [choices, out](const std::string& v) {
    for (const std::string& c : choices) {
      if (v == c) {
        *out = v;
        return std::string();
      }
    }
    return "takes " + Join(choices, ", ") + ", not '" + v + "'";
  });
}

CliArgs& CliArgs::Required() {
  if (!options_.empty()) options_.back().required = true;
  return *this;
}

CliArgs& CliArgs::First() {
  if (!options_.empty()) options_.back().first = true;
  return *this;
}

CliArgs& CliArgs::Positional(const std::string& name, std::vector<std::string>* out, size_t min,
                             size_t max) {
  positional_name_ = name;
  positional_ = out;
  positional_min_ = min;
  positional_max_ = max;
  return *this;
}

CliArgs& CliArgs::Epilog(const std::string& text) {
  epilog_ = text;
  return *this;
}

CliArgs& CliArgs::VersionDetail(const std::string& text) {
  version_detail_ = text;
  return *this;
}

CliArgs::Option* CliArgs::Find(const std::string& name) {
  for (Option& o : options_) {
    for (const std::string& n : o.names) {
      if (n == name) return &o;
    }
  }
  return nullptr;
}

const CliArgs::Option* CliArgs::Find(const std::string& name) const {
  return const_cast<CliArgs*>(this)->Find(name);
}

bool CliArgs::Seen(const std::string& name) const {
  const Option* o = Find(name);
  return o != nullptr && o->seen;
}

int CliArgs::UsageError(const std::string& message) const {
  std::fprintf(stderr, "%s: %s (usage: %s %s; see --help)\n", program_.c_str(), message.c_str(),
               program_.c_str(), synopsis_.c_str());
  return kExitUsage;
}

std::string CliArgs::Help() const {
  std::string out = "usage: " + program_ + " " + synopsis_ + "\n";
  if (!summary_.empty()) out += summary_ + (summary_.back() == '\n' ? "" : "\n");
  out += "options:\n";
  for (const Option& o : options_) {
    std::string names = Join(o.names, ", ");
    if (!o.value_name.empty()) names += " " + o.value_name;
    out += HelpEntry(names, o.help + (o.required ? " (required)" : ""));
  }
  out += HelpEntry("-h, --help", "print this help and exit");
  out += HelpEntry("--version", "print the version and exit");
  if (!epilog_.empty()) out += "\n" + epilog_ + (epilog_.back() == '\n' ? "" : "\n");
  return out;
}

std::string CliArgs::Version() const {
  const bool ours = program_.compare(0, 8, "hullpack") == 0;
  std::string out = program_ + (ours ? " " : " (hullpack) ") + HULLPACK_VERSION + "\n";
  if (!version_detail_.empty())
    out += version_detail_ + (version_detail_.back() == '\n' ? "" : "\n");
  return out;
}

std::optional<int> CliArgs::Parse(int argc, char** argv) {
  return Parse(std::vector<std::string>(argv + (argc > 0 ? 1 : 0), argv + (argc > 0 ? argc : 0)));
}

std::optional<int> CliArgs::Parse(const std::vector<std::string>& args) {
  // --help and --version win wherever they stand, so that they work even on a wrong command line.
  for (const std::string& a : args) {
    if (a == "--") break;
    if (a == "-h" || a == "--help") {
      std::fputs(Help().c_str(), stdout);
      return 0;
    }
    if (a == "--version") {
      std::fputs(Version().c_str(), stdout);
      return 0;
    }
  }
  // Split into (option, spelling, value) in command-line order, then apply the First() options
  // before the others.
  struct Given {
    Option* option;
    std::string spelling, value;
  };
  std::vector<Given> given;
  std::vector<std::string> operands;
  bool options_ended = false;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (options_ended || a.size() < 2 || a[0] != '-') {
      operands.push_back(a);
      continue;
    }
    if (a == "--") {
      options_ended = true;
      continue;
    }
    std::string spelling = a, value;
    bool inline_value = false;
    const size_t equals = a.find('=');
    if (a.compare(0, 2, "--") == 0 && equals != std::string::npos) {
      spelling = a.substr(0, equals);
      value = a.substr(equals + 1);
      inline_value = true;
    }
    Option* o = Find(spelling);
    if (o == nullptr) return UsageError("unknown option '" + spelling + "'");
    if (o->value_name.empty()) {
      if (inline_value) return UsageError(spelling + " takes no value");
    } else if (!inline_value) {
      if (i + 1 >= args.size())
        return UsageError(spelling + " needs a value (" + o->value_name + ")");
      value = args[++i];
    }
    given.push_back({o, spelling, value});
  }
  for (int pass = 0; pass < 2; ++pass) {
    for (Given& g : given) {
      if (g.option->first != (pass == 0)) continue;
      const std::string why = g.option->apply(g.value);
      if (!why.empty()) return UsageError(g.spelling + " " + why);
      g.option->seen = true;
    }
  }
  for (const Option& o : options_) {
    if (o.required && !o.seen) return UsageError("missing " + o.names.back() + " " + o.value_name);
  }
  if (positional_ == nullptr && !operands.empty())
    return UsageError("unexpected argument '" + operands[0] + "'");
  if (positional_ != nullptr) {
    if (operands.size() < positional_min_) return UsageError("missing " + positional_name_);
    if (operands.size() > positional_max_) {
      return UsageError("unexpected argument '" + operands[positional_max_] + "' (" +
                        (positional_max_ == 1 ? "one " + positional_name_ + " at a time"
                                              : "at most " + std::to_string(positional_max_) + " " +
                                                    positional_name_) +
                        ")");
    }
    *positional_ = operands;
  }
  return std::nullopt;
}

std::string CliArgs::ParseWholeNumber(const std::string& text, long long lo, long long hi,
                                      long long* out) {
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || errno != 0 || v < lo || v > hi) {
    return "takes a whole number in [" + std::to_string(lo) + ", " + std::to_string(hi) +
           "], not '" + text + "'";
  }
  *out = v;
  return "";
}

std::string CliArgs::ParseNumber(const std::string& text, double lo, double hi, double* out) {
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || errno != 0 || !std::isfinite(v) || !(v >= lo && v <= hi)) {
    char range[96];
    std::snprintf(range, sizeof(range), "[%g, %g]", lo, hi);
    return std::string("takes a number in ") + range + ", not '" + text + "'";
  }
  *out = v;
  return "";
}

}  // namespace hullpack
