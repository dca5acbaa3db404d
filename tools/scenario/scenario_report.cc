// mjbuoy-scenario: console report and JUnit XML
#include <cstdio>

#include <tinyxml2.h>

#include "scenario.h"

namespace scn {

bool Report::passed() const {
  if (invalid) return false;
  for (const Result& r : results) {
    if (!r.pass) return false;
  }
  return true;
}

void printReport(const Report& r, FILE* out) {
  std::fprintf(out, "mjbuoy-scenario: %s\n", r.file.c_str());
  if (r.invalid) {
    std::fprintf(out, "%s: INVALID\n", r.file.c_str());
    return;
  }
  std::fprintf(out, "  %s\n", r.header.c_str());
  int failed = 0;
  for (const Result& x : r.results) {
    std::fprintf(out, "%s %s: %s\n", x.pass ? "ok  " : "FAIL", x.label.c_str(), x.detail.c_str());
    failed += !x.pass;
  }
  if (failed) {
    std::fprintf(out, "%s: FAILED %d of %zu\n", r.file.c_str(), failed, r.results.size());
  } else {
    std::fprintf(out, "%s: passed %zu check(s)\n", r.file.c_str(), r.results.size());
  }
}

static std::string fixed(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.3f", v);
  return buf;
}

bool writeJUnit(const std::vector<Report>& reports, FILE* f) {
  tinyxml2::XMLDocument doc;
  doc.InsertEndChild(doc.NewDeclaration());
  tinyxml2::XMLElement* all = doc.NewElement("testsuites");
  doc.InsertEndChild(all);
  int tests = 0, failures = 0, errors = 0;
  double time = 0;
  for (const Report& r : reports) {
    tinyxml2::XMLElement* suite = doc.NewElement("testsuite");
    all->InsertEndChild(suite);
    int f = 0;
    suite->SetAttribute("name", r.name.c_str());
    suite->SetAttribute("file", r.file.c_str());
    if (r.invalid) {
      tinyxml2::XMLElement* tc = doc.NewElement("testcase");
      tc->SetAttribute("classname", ("mjbuoy-scenario." + r.name).c_str());
      tc->SetAttribute("name", "load scenario");
      tc->SetAttribute("time", "0");
      tinyxml2::XMLElement* e = doc.NewElement("error");
      e->SetAttribute("type", "invalid");
      e->SetAttribute("message", r.error.c_str());
      e->SetText(r.error.c_str());
      tc->InsertEndChild(e);
      suite->InsertEndChild(tc);
      errors++;
      tests++;
      suite->SetAttribute("tests", 1);
      suite->SetAttribute("failures", 0);
      suite->SetAttribute("errors", 1);
    } else {
      for (const Result& x : r.results) {
        tinyxml2::XMLElement* tc = doc.NewElement("testcase");
        tc->SetAttribute("classname", ("mjbuoy-scenario." + r.name).c_str());
        tc->SetAttribute("name", x.label.c_str());
        tc->SetAttribute("time", "0");
        if (!x.pass) {
          tinyxml2::XMLElement* e = doc.NewElement("failure");
          e->SetAttribute("type", x.kind.c_str());
          e->SetAttribute("message", x.detail.c_str());
          e->SetText(("FAIL " + x.label + ": " + x.detail).c_str());
          tc->InsertEndChild(e);
          f++;
        }
        suite->InsertEndChild(tc);
      }
      tests += (int)r.results.size();
      failures += f;
      suite->SetAttribute("tests", (int)r.results.size());
      suite->SetAttribute("failures", f);
      suite->SetAttribute("errors", 0);
      tinyxml2::XMLElement* so = doc.NewElement("system-out");
      so->SetText(r.header.c_str());
      suite->InsertEndChild(so);
    }
    suite->SetAttribute("time", fixed(r.wall).c_str());
    time += r.wall;
  }
  all->SetAttribute("name", "mjbuoy-scenario");
  all->SetAttribute("tests", tests);
  all->SetAttribute("failures", failures);
  all->SetAttribute("errors", errors);
  all->SetAttribute("time", fixed(time).c_str());
  return doc.SaveFile(f) == tinyxml2::XML_SUCCESS && !std::ferror(f);
}

}  // namespace scn
