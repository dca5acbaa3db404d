// mjbuoy-sim --set, --spectrum and --calm (simsea.h): the entries are
// checked for form here (name, value present, numbers for a numeric entry)
// and for meaning by mjbuoy itself (mjb_attach: known entry, count, range)
#include "simsea.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include <tinyxml2.h>

#include "mjcfedit.h"

namespace mjbsim {

// every whitespace-separated token a finite number (and at least one)
static bool numbers(const std::string& v) {
  std::istringstream in(v);
  std::string tok;
  int n = 0;
  while (in >> tok) {
    errno = 0;
    char* end = nullptr;
    double x = std::strtod(tok.c_str(), &end);
    if (end == tok.c_str() || *end || !std::isfinite(x) || errno == ERANGE) return false;
    n++;
  }
  return n > 0;
}

// every token a number as strtod reads it, NaN and infinities included: the
// value was meant as numbers (a <numeric> entry), finite or not
static bool looksNumeric(const std::string& v) {
  std::istringstream in(v);
  std::string tok;
  int n = 0;
  while (in >> tok) {
    char* end = nullptr;
    std::strtod(tok.c_str(), &end);
    if (end == tok.c_str() || *end) return false;
    n++;
  }
  return n > 0;
}

static std::string add(Edits* out, const std::string& name, const std::string& data,
                       const std::string& given) {
  if (name.rfind("mjbuoy.", 0) != 0 || name.size() == 7) {
    return given + ": \"" + name + "\" is not an mjbuoy entry; names start with mjbuoy., "
           "e.g. --set mjbuoy.spectrum.sea.hs=1 (docs/mjcf.md)";
  }
  if (name.find_first_of(" \t\n\"<>&") != std::string::npos) {
    return given + ": entry name \"" + name + "\" holds a space or one of \"<>&";
  }
  if (data.find_first_not_of(" \t") == std::string::npos) {
    return given + ": no value for " + name + "; give NAME=VALUE, e.g. " + name + "=1";
  }
  for (size_t i = 0; i < out->set.size(); i++) {
    if (out->set[i].first == name) {
      return given + ": " + name + " is already set by " + out->given[i] +
             "; set each entry once";
    }
  }
  out->set.emplace_back(name, data);
  out->given.push_back(given);
  return "";
}

// "[LABEL=]TYPE[:FIELD=VALUE,...]" (values of several numbers: spaces,
// e.g. range=1 8)
static std::string spectrum(const std::string& arg, Edits* out) {
  std::string given = "--spectrum " + arg, label = "cli", rest = arg;
  size_t colon = rest.find(':'), eq = rest.find('=');
  if (eq != std::string::npos && eq < colon) {
    label = rest.substr(0, eq);
    rest = rest.substr(eq + 1);
    colon = rest.find(':');
  }
  std::string type = rest.substr(0, colon);
  if (label.empty() || type.empty()) {
    return given + ": expected [LABEL=]TYPE[:FIELD=VALUE,...], e.g. jonswap:hs=1,tp=6";
  }
  std::string pre = "mjbuoy.spectrum." + label + ".";
  std::string e = add(out, pre + "type", type, given);
  if (!e.empty()) return e;
  if (colon == std::string::npos) return "";
  std::istringstream in(rest.substr(colon + 1));
  std::string kv;
  while (std::getline(in, kv, ',')) {
    size_t q = kv.find('=');
    if (q == std::string::npos || q == 0) {
      return given + ": \"" + kv + "\" is not FIELD=VALUE (fields: docs/mjcf.md section 8)";
    }
    e = add(out, pre + kv.substr(0, q), kv.substr(q + 1), given);
    if (!e.empty()) return e;
  }
  return "";
}

std::string parseEdits(const std::vector<std::string>& sets,
                       const std::vector<std::string>& spectra, bool calm, Edits* out) {
  out->calm = calm;
  for (const std::string& s : sets) {
    size_t q = s.find('=');
    if (q == std::string::npos) {
      return "--set " + s + ": expected NAME=VALUE, e.g. --set mjbuoy.spectrum.sea.hs=1";
    }
    std::string e = add(out, s.substr(0, q), s.substr(q + 1), "--set " + s);
    if (!e.empty()) return e;
  }
  for (const std::string& s : spectra) {
    std::string e = spectrum(s, out);
    if (!e.empty()) return e;
  }
  return "";
}

// the edits applied to doc, the MJCF of model, printed into xml
static bool editDoc(const std::string& model, tinyxml2::XMLDocument& doc, const Edits& ed,
                    std::string* xml, std::string* err) {
  tinyxml2::XMLElement* root = doc.RootElement();
  if (!root || std::string(root->Name()) != "mujoco") {
    *err = model + " is not MJCF (root element <mujoco>)";
    return false;
  }
  if (ed.calm) mjbtool::removeSea(root);
  for (size_t i = 0; i < ed.set.size(); i++) {
    const std::string& name = ed.set[i].first;
    const std::string& data = ed.set[i].second;
    // the kind the model gives the entry, else numeric when the value is numbers
    tinyxml2::XMLElement* old = mjbtool::findEntry(root, name);
    bool text = old ? std::string(old->Name()) == "text" : !looksNumeric(data);
    if (!text && !numbers(data)) {
      *err = ed.given[i] + ": " + name + (old ? " is a <numeric> entry of " + model + " and" : "") +
             " \"" + data + "\" is not a list of finite numbers; mjbuoy's numbers are finite";
      return false;
    }
    mjbtool::setEntry(doc, root, name, data, text);
  }
  tinyxml2::XMLPrinter p;
  doc.Print(&p);
  *xml = p.CStr();
  return true;
}

bool editedModel(const std::string& model, const Edits& ed, std::string* xml,
                 std::string* err) {
  tinyxml2::XMLDocument doc;
  if (doc.LoadFile(model.c_str()) != tinyxml2::XML_SUCCESS) {
    *err = "cannot read " + model + ": " + doc.ErrorStr();
    return false;
  }
  return editDoc(model, doc, ed, xml, err);
}

bool editedText(const std::string& model, const std::string& text, const Edits& ed,
                std::string* xml, std::string* err) {
  tinyxml2::XMLDocument doc;
  if (doc.Parse(text.c_str(), text.size()) != tinyxml2::XML_SUCCESS) {
    *err = "cannot parse " + model + ": " + doc.ErrorStr();
    return false;
  }
  return editDoc(model, doc, ed, xml, err);
}

std::string blame(const Edits& ed, const std::string& err) {
  for (size_t i = 0; i < ed.set.size(); i++) {
    if (err.find("\"" + ed.set[i].first + "\"") != std::string::npos) {
      return ed.given[i] + ": " + err;
    }
  }
  return err;
}

}  // namespace mjbsim
