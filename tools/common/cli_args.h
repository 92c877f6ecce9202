// The command-line convention of every hullpack program: options are declared once (names, value,
// range, help), and the parser derives the rest. `--help`/`-h` prints the usage to stdout and exits
// 0, `--version` prints the version and exits 0, and any usage error prints one line to stderr and
// exits 64 (kExitUsage). `--name=value` and `--name value` are the same; `--` ends the options.
//
//   hullpack::CliArgs cli("hullpack unpack", "PACKED.glb -o OUTPUT [options]",
//                         "Decodes a packed GLB back to plain glTF, OBJ, ...");
//   cli.String("-o, --output", "OUTPUT", &output, "the file to write").Required();
//   cli.Flag("--force", &force, "replace an existing OUTPUT");
//   cli.Positional("PACKED.glb", &inputs, 1, 1);
//   if (std::optional<int> exit_code = cli.Parse(argc, argv)) return *exit_code;
#ifndef HULLPACK_TOOLS_COMMON_CLI_ARGS_H_
#define HULLPACK_TOOLS_COMMON_CLI_ARGS_H_

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace hullpack {

constexpr int kExitUsage = 64;  // sysexits' EX_USAGE: the command line is wrong

class CliArgs {
 public:
  // Applies an option's value; returns "" when it is accepted, else the reason (one line).
  using Apply = std::function<std::string(const std::string& value)>;

  // `program` names the program in messages ("hullpack pack"); `synopsis` follows it on the usage
  // line; `summary` (one or more lines) says what the program does.
  CliArgs(std::string program, std::string synopsis, std::string summary = "");

  // `names` lists the spellings, comma-separated ("-o, --output"); the help text may hold '\n'.
  CliArgs& Flag(const std::string& names, bool* out, const std::string& help);
  CliArgs& String(const std::string& names, const std::string& value_name, std::string* out,
                  const std::string& help);
  CliArgs& Double(const std::string& names, const std::string& value_name, double lo, double hi,
                  double* out, const std::string& help);
  // A whole number in [lo, hi], stored into any integer type.
  template <typename T>
  CliArgs& Int(const std::string& names, const std::string& value_name, long long lo, long long hi,
               T* out, const std::string& help) {
    return Value(names, value_name, help, [lo, hi, out](const std::string& v) {
      long long n = 0;
      std::string why = ParseWholeNumber(v, lo, hi, &n);
      if (why.empty()) *out = static_cast<T>(n);
      return why;
    });
  }
  // One of `choices`, stored as given.
  CliArgs& Choice(const std::string& names, const std::vector<std::string>& choices,
                  std::string* out, const std::string& help);
  // A value option with its own parsing.
  CliArgs& Value(const std::string& names, const std::string& value_name, const std::string& help,
                 Apply apply);
  // A flag with its own effect.
  CliArgs& Action(const std::string& names, const std::string& help, std::function<void()> apply);

  // Modifiers of the option declared last: Required() makes leaving it out a usage error; First()
  // applies it before every other option wherever it stands (a preset the others refine).
  CliArgs& Required();
  CliArgs& First();

  // The operands (arguments that are not options), between `min` and `max` of them.
  CliArgs& Positional(const std::string& name, std::vector<std::string>* out, size_t min,
                      size_t max = SIZE_MAX);
  // Text printed after the options in --help (examples, legacy forms).
  CliArgs& Epilog(const std::string& text);
  // Printed by --version after the program version (e.g. the format versions it writes and reads).
  CliArgs& VersionDetail(const std::string& text);

  // Parses the arguments (without the program name). Returns an exit code when the program should
  // stop (0 after --help or --version, kExitUsage after a usage error, already reported), or
  // nothing when it should go on.
  std::optional<int> Parse(const std::vector<std::string>& args);
  std::optional<int> Parse(int argc, char** argv);

  // Whether the option (any of its spellings) was given.
  bool Seen(const std::string& name) const;
  // Reports a usage error found after parsing (one line on stderr); returns kExitUsage.
  int UsageError(const std::string& message) const;
  std::string Help() const;
  std::string Version() const;
  const std::string& program() const { return program_; }

  // "" when `text` is a whole number in [lo, hi], else the reason.
  static std::string ParseWholeNumber(const std::string& text, long long lo, long long hi,
                                      long long* out);
  // "" when `text` is a finite number in [lo, hi], else the reason.
  static std::string ParseNumber(const std::string& text, double lo, double hi, double* out);

 private:
  struct Option {
    std::vector<std::string> names;
    std::string value_name;  // empty for flags
    std::string help;
    Apply apply;
    bool required = false;
    bool first = false;
    bool seen = false;
  };
  Option* Find(const std::string& name);
  const Option* Find(const std::string& name) const;
  CliArgs& Add(Option option);

  std::string program_, synopsis_, summary_, epilog_, version_detail_;
  std::vector<Option> options_;
  std::string positional_name_;
  std::vector<std::string>* positional_ = nullptr;
  size_t positional_min_ = 0, positional_max_ = 0;
};

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_COMMON_CLI_ARGS_H_
