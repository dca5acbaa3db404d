// scenario files and sweep files: one XML element with its allowed
// attributes, whose accessors validate and throw Invalid "FILE:LINE: reason"
// (shared by scenario_parse.cc and sweep_parse.cc)
#ifndef MJBUOY_TOOLS_SCENARIO_XML_H_
#define MJBUOY_TOOLS_SCENARIO_XML_H_

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include <tinyxml2.h>

#include "scenario.h"

namespace scn {

using tinyxml2::XMLAttribute;
using tinyxml2::XMLElement;

inline std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (size_t i = 0; i < v.size(); i++) s += (i ? ", " : "") + v[i];
  return s;
}

// one element with its allowed attributes; every accessor validates
class El {
 public:
  El(const XMLElement* e, const std::string& file, const std::vector<std::string>& allowed)
      : e_(e), file_(file) {
    for (const XMLAttribute* a = e->FirstAttribute(); a; a = a->Next()) {
      bool ok = false;
      for (auto& n : allowed) ok = ok || n == a->Name();
      if (!ok) {
        throw Invalid(file_, a->GetLineNum(),
                      "unknown attribute '" + std::string(a->Name()) + "' of <" + tag() +
                          (has("kind") && tag() == "check" ? " kind=\"" + str("kind") + "\"" : "") +
                          ">; allowed: " + joined(allowed));
      }
    }
  }
  std::string tag() const { return e_->Name(); }
  int line() const { return e_->GetLineNum(); }
  bool has(const char* a) const { return e_->FindAttribute(a) != nullptr; }
  int line(const char* a) const {
    const XMLAttribute* at = e_->FindAttribute(a);
    return at ? at->GetLineNum() : line();
  }
  [[noreturn]] void fail(const std::string& why, const char* attr = nullptr) const {
    throw Invalid(file_, attr ? line(attr) : line(), "<" + tag() + ">: " + why);
  }
  std::string str(const char* a) const {
    if (!has(a)) fail(std::string("missing attribute '") + a + "'");
    return e_->Attribute(a);
  }
  std::string str(const char* a, const std::string& def) const { return has(a) ? str(a) : def; }
  // exactly n whitespace-separated finite numbers
  std::vector<double> numbers(const char* a, int n, const char* what) const {
    std::vector<double> v = parseNumbers(a, str(a));
    if (n > 0 && (int)v.size() != n) {
      fail(std::string("attribute ") + a + "=\"" + str(a) + "\" has " + std::to_string(v.size()) +
               " value(s), expected " + std::to_string(n) + " (" + what + ")",
           a);
    }
    return v;
  }
  double number(const char* a) const { return numbers(a, 1, "one number")[0]; }
  double number(const char* a, double def) const { return has(a) ? number(a) : def; }
  bool flag(const char* a) const {
    std::string v = str(a, "false");
    if (v == "true") return true;
    if (v == "false") return false;
    fail(std::string("attribute ") + a + "=\"" + v + "\" must be true or false", a);
  }
  std::vector<double> parseNumbers(const char* a, const std::string& text) const {
    std::vector<double> v;
    std::istringstream in(text);
    std::string tok;
    while (in >> tok) {
      errno = 0;
      char* end = nullptr;
      double x = std::strtod(tok.c_str(), &end);
      if (end == tok.c_str() || *end || !std::isfinite(x) || errno == ERANGE) {
        fail(std::string("bad number '") + tok + "' in attribute " + a + "=\"" + text +
                 "\" (finite decimal numbers only)",
             a);
      }
      v.push_back(x);
    }
    if (v.empty()) fail(std::string("attribute ") + a + " is empty; it needs numbers", a);
    return v;
  }

 private:
  const XMLElement* e_;
  const std::string& file_;
};

}  // namespace scn

#endif  // MJBUOY_TOOLS_SCENARIO_XML_H_
