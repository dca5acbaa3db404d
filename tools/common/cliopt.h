// cliopt: numeric command-line options of the tools. CLI11's own number
// checks (PositiveNumber, Range) let NaN through, since every comparison
// with NaN is false; Finite refuses NaN and infinities and names the range
// compactly ("(0, inf)", not DBL_MAX in full). CLI11 puts the option's name
// in front of the message.
#ifndef MJBUOY_TOOLS_CLIOPT_H_
#define MJBUOY_TOOLS_CLIOPT_H_

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>

#include <CLI/CLI.hpp>

namespace mjbtool {

constexpr double kInf = std::numeric_limits<double>::infinity();

// a bound for messages: %g, "inf" for infinities
inline std::string bound(double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char b[32];
  std::snprintf(b, sizeof(b), "%g", v);
  return b;
}

// a finite number in [lo, hi]; loOpen / hiOpen exclude the bound. An
// infinite bound is always open (only finite values pass)
inline CLI::Validator Finite(double lo, double hi, bool loOpen = false, bool hiOpen = false) {
  loOpen = loOpen || std::isinf(lo);
  hiOpen = hiOpen || std::isinf(hi);
  std::string range = std::string(loOpen ? "(" : "[") + bound(lo) + ", " + bound(hi) +
                      (hiOpen ? ")" : "]");
  return CLI::Validator(
      [=](std::string& s) -> std::string {
        const char* c = s.c_str();
        char* end = nullptr;
        double v = std::strtod(c, &end);
        if (end == c || *end != 0) return "'" + s + "' is not a number; expected one in " + range;
        if (!std::isfinite(v)) return s + " is not a finite number; expected one in " + range;
        if (v < lo || v > hi || (loOpen && v == lo) || (hiOpen && v == hi)) {
          return s + " is outside " + range;
        }
        return std::string();
      },
      "in " + range, "finite in " + range);
}

// parse the command line: -1 to go on, else the exit status. --help and
// --version exit 0; a usage error (unknown option, missing or refused
// value) prints CLI11's message and exits with usage, the status the tool
// documents for invalid input (CLI11's own codes, 105 or 106, are not in
// any tool's documentation)
inline int parseArgs(CLI::App& app, int argc, char** argv, int usage) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : usage;
  }
  return -1;
}

}  // namespace mjbtool

#endif  // MJBUOY_TOOLS_CLIOPT_H_
