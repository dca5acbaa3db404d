// mjbuoy-sweep merge: the results of DIR/cases into one CSV (a row per
// case), a JUnit file (a suite per case), plots and a summary (docs/sweeps.md).
// Only what a case computed goes into the CSV and JUnit, not how long it
// took, so they are identical however the sweep was run.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "atomic.h"
#include "outfile.h"
#include "sweep.h"

namespace swp {

namespace fs = std::filesystem;
using json = nlohmann::json;

static bool load(const std::string& path, json* j) {
  if (!notRegular(path).empty()) return false;
  std::ifstream in(path);
  if (!in) return false;
  try { in >> *j; return true; } catch (...) { return false; }
}

static std::string csvField(const std::string& v) {
  if (v.find_first_of(",\"\n") == std::string::npos) return v;
  std::string q = "\"";
  for (char c : v) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

static std::string statText(const json& v) {
  return v.is_number() ? scn::exact(v.get<double>()) : std::string();
}

// a case's result as a scenario report for the JUnit writer
static scn::Report report(const json& man, const json& r, const std::string& id) {
  scn::Report rep;
  rep.file = man.value("file", "");
  rep.name = man.value("sweep", "") + "." + id;
  std::string st = r.value("status", "missing");
  if (st == "invalid") {
    rep.invalid = true;
    rep.error = r.value("error", "");
  } else if (st == "crash" || st == "missing" || st == "stale") {
    scn::Result x;
    x.label = st == "crash" ? "case process" : "result";
    x.kind = st;
    x.pass = false;
    x.detail = st != "missing" ? r.value("error", "") : "no result for this case (not run yet?)";
    rep.results.push_back(x);
  } else {
    rep.header = r.value("header", "");
    for (const json& c : r["checks"]) {
      rep.results.push_back({c.value("label", ""), c.value("kind", ""), c.value("pass", false),
                             c.value("detail", "")});
    }
  }
  return rep;
}

// one plot: y against x, a curve per value of curves, drawn by gnuplot into
// DIR/plots/<y>-<x>[-<curves>].png
static bool plot(const std::string& dir, const json& man, const json& p,
                 const std::vector<json>& res, std::string* msg) {
  std::string y = p["y"], x = p["x"], cv = p["curves"];
  std::map<std::string, int> axisAt;
  for (size_t a = 0; a < man["axes"].size(); a++) axisAt[man["axes"][a]["name"]] = (int)a;
  auto value = [&](const json& r, const std::string& n) -> std::string {
    if (axisAt.count(n)) return r["axes"].value(n, "");
    return r.contains("stats") ? statText(r["stats"].value(n, json())) : "";
  };
  std::vector<std::string> curves = {""};
  if (!cv.empty()) curves = man["axes"][axisAt[cv]]["values"].get<std::vector<std::string>>();
  std::string stem = y + "-" + x + (cv.empty() ? "" : "-" + cv);
  fs::path pd = fs::path(dir) / "plots";
  fs::create_directories(pd);
  std::string data, err;
  int n = 0;
  for (const std::string& cvv : curves) {
    data += "\n\n# " + (cv.empty() ? y : cv + " = " + cvv) + "\n";
    for (size_t i = 0; i < res.size(); i++) {
      const json& r = res[i];
      if (!r.contains("axes")) continue;
      // against an axis, the other axes at their first value; against a
      // statistic, every case
      bool first = true;
      for (auto& [name, a] : axisAt) {
        if (!axisAt.count(x) || name == x || name == cv) continue;
        first = first && r["axes"].value(name, "") == man["axes"][a]["values"][0].get<std::string>();
      }
      if (!first || (!cv.empty() && r["axes"].value(cv, "") != cvv)) continue;
      std::string xv = value(r, x), yv = value(r, y);
      if (xv.empty() || yv.empty()) continue;
      data += xv + " " + yv + "\n";
      n++;
    }
  }
  if (!n) { *msg = stem + ": no points"; return false; }
  std::string dat = (pd / (stem + ".dat")).string(), png = (pd / (stem + ".png")).string();
  if (!atomicfile::write(dat, data.substr(2), &err)) { *msg = err; return false; }
  std::string gp = "set terminal pngcairo noenhanced size 800,560\nset grid\nset key outside right\n";
  gp += "set xlabel '" + x + "'\nset ylabel '" + y + "'\n";
  std::string title = p.value("title", "");
  gp += "set title '" + (title.empty() ? man.value("sweep", "") + ": " + y : title) + "'\n";
  if (p.value("logx", false)) gp += "set logscale x\n";
  if (p.value("logy", false)) gp += "set logscale y\n";
  gp += "plot ";
  for (size_t k = 0; k < curves.size(); k++) {
    gp += (k ? ", " : "") + std::string("'") + dat + "' index " + std::to_string(k) +
          " using 1:2 with linespoints title '" + (cv.empty() ? y : cv + " = " + curves[k]) + "'";
  }
  gp += "\n";
  std::string gpf = (pd / (stem + ".gp")).string();
  if (!atomicfile::write(gpf, gp, &err)) { *msg = err; return false; }
  bool ok = atomicfile::commit(png, [&](const std::string& tmp) {
    std::string cmd = "gnuplot -e \"set output '" + tmp + "'\" '" + gpf + "' 2>&1";
    return std::system(cmd.c_str()) == 0 && fs::file_size(tmp) > 0;
  }, &err);
  *msg = ok ? png : "gnuplot failed for " + gpf + " (is gnuplot installed? Debian: gnuplot-nox)";
  return ok;
}

// the default plots: every statistic against the first axis, a curve per
// value of the second
// the JUnit report, written atomically (tools/common/outfile.h)
static bool writeJUnitFile(const std::vector<scn::Report>& reps, const std::string& path,
                           std::string* err) {
  mjbtool::OutFile o;
  if (!o.open(path, path, err)) return false;
  if (!scn::writeJUnit(reps, o.file())) {
    *err = "cannot write " + path;
    return false;
  }
  return o.commit(err);
}

static json defaultPlots(const json& man) {
  json plots = json::array();
  if (man["axes"].empty()) return plots;
  for (const json& s : man["stats"]) {
    plots.push_back({{"y", s["name"]}, {"x", man["axes"][0]["name"]},
                     {"curves", man["axes"].size() > 1 ? man["axes"][1]["name"] : json("")},
                     {"title", ""}, {"logx", false}, {"logy", false}});
  }
  return plots;
}

int merge(const std::string& dir) {
  json man;
  std::string mpath = (fs::path(dir) / "sweep.json").string();
  if (!load(mpath, &man)) {
    std::fprintf(stderr, "mjbuoy-sweep: no sweep in %s (%s missing: run the sweep first)\n",
                 dir.c_str(), mpath.c_str());
    return 2;
  }
  for (const json& c : man["cases"]) {
    std::string why = notRegular(resultPath(dir, c["id"]));
    if (!why.empty()) {
      std::fprintf(stderr, "mjbuoy-sweep: %s\n", why.c_str());
      return 2;
    }
  }
  // results of files that changed since the run are stale: the hashes as
  // the files are now (the sweep file must still parse to tell)
  std::vector<std::string> now;
  try {
    Sweep s = parseSweep(man.value("file", ""));
    if (!checkSweepOutputs(s, {(fs::path(dir) / "sweep.csv").string(),
                               (fs::path(dir) / "junit.xml").string()})) {
      return 2;
    }
    if (s.ncases == (long)man["cases"].size()) now = caseHashes(s);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mjbuoy-sweep: warning: cannot tell whether the results are current "
                 "(the sweep file does not load: %s)\n", e.what());
  }
  std::vector<json> res;
  std::map<std::string, int> count;
  size_t ci = 0;
  double wall = 0, maxwall = 0;
  long maxrss = 0;
  std::string csv = "id";
  for (const json& a : man["axes"]) csv += "," + csvField(a["name"]);
  csv += ",status";
  for (const json& s : man["stats"]) csv += "," + csvField(s["name"]);
  csv += ",checks,failed,failures\n";
  std::vector<scn::Report> reps;
  std::vector<std::string> bad;
  for (const json& c : man["cases"]) {
    std::string id = c["id"];
    json r;
    if (!load(resultPath(dir, id), &r) || r.value("hash", "") != c["hash"].get<std::string>()) {
      r = json::object();
      r["status"] = "missing";
    } else if (!now.empty() && now[ci] != c["hash"].get<std::string>()) {
      // the model, a mesh, an include or mjbuoy changed since: not published
      json h = json::object();
      h["status"] = "stale";
      h["error"] = "a file the case reads (model, mesh, include) or mjbuoy changed since it ran; "
                   "run the sweep again to update it";
      if (r.contains("axes")) h["axes"] = r["axes"];
      r = h;
    }
    ci++;
    std::string st = r.value("status", "missing");
    count[st]++;
    if (st != "pass") bad.push_back(id + ": " + st);
    wall += r.value("wall_s", 0.0);
    maxwall = std::max(maxwall, r.value("wall_s", 0.0));
    maxrss = std::max(maxrss, r.value("maxrss_kb", 0L));
    csv += csvField(id);
    for (const json& a : man["axes"]) {
      csv += "," + csvField(r.contains("axes") ? r["axes"].value(a["name"].get<std::string>(), "") : "");
    }
    csv += "," + st;
    for (const json& s : man["stats"]) {
      csv += "," + (r.contains("stats") ? statText(r["stats"].value(s["name"].get<std::string>(), json())) : "");
    }
    int nc = 0, nf = 0;
    std::string fails;
    if (r.contains("checks")) {
      for (const json& k : r["checks"]) {
        nc++;
        if (!k.value("pass", false)) fails += (nf++ ? "; " : "") + k.value("label", "");
      }
    }
    if (r.contains("error")) fails += (fails.empty() ? "" : "; ") + r.value("error", "");
    csv += "," + std::to_string(nc) + "," + std::to_string(nf) + "," + csvField(fails) + "\n";
    reps.push_back(report(man, r, id));
    res.push_back(r);
  }
  std::string err, csvp = (fs::path(dir) / "sweep.csv").string(), jp = (fs::path(dir) / "junit.xml").string();
  if (!atomicfile::write(csvp, csv, &err) ||
      !writeJUnitFile(reps, jp, &err)) {
    std::fprintf(stderr, "mjbuoy-sweep: %s\n", err.c_str());
    return 2;
  }
  std::printf("mjbuoy-sweep: %s: %zu case(s):", man.value("sweep", "").c_str(), man["cases"].size());
  for (auto& [k, n] : count) std::printf(" %d %s", n, k.c_str());
  std::printf("\n  per case: wall %.3f s mean, %.3f s max; peak RSS %.1f MiB max\n",
              res.empty() ? 0 : wall / res.size(), maxwall, maxrss / 1024.0);
  for (size_t i = 0; i < bad.size() && i < 20; i++) std::printf("  not passed: %s\n", bad[i].c_str());
  if (bad.size() > 20) std::printf("  ... and %zu more (see the CSV)\n", bad.size() - 20);
  std::printf("  %s\n  %s\n", csvp.c_str(), jp.c_str());
  json plots = man["plots"].empty() ? defaultPlots(man) : man["plots"];
  for (const json& p : plots) {
    std::string msg;
    bool ok = plot(dir, man, p, res, &msg);
    std::printf("  %s%s\n", ok ? "" : "no plot: ", msg.c_str());
  }
  return bad.empty() ? 0 : 1;
}

}  // namespace swp
