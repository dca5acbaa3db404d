// radcache: panel solver results on disk (radcache.h). File layout, all
// little-endian as the machine writes it (a file from another byte order
// fails its checksum or version and is recomputed):
//   magic "MJBRADC\n" | u32 format | u32 solver version | u64 n, key bytes |
//   u64 n, coefficient bytes | u64 FNV-1a checksum of everything before
#include "radiation/radcache.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace mjb {

static const char kMagic[8] = {'M', 'J', 'B', 'R', 'A', 'D', 'C', '\n'};
static const uint32_t kFormat = 1;
static const uint64_t kMaxFile = uint64_t(1) << 30;  // 1 GiB: larger is not ours

// FNV-1a 64 (Fowler, Noll, Vo): file name and checksum; the key itself is
// compared byte for byte, so a collision cannot return another hull's data
static uint64_t fnv(const std::string& s) {
  uint64_t h = 1469598103934665603ull;
  for (unsigned char c : s) h = (h ^ c) * 1099511628211ull;
  return h;
}

static void put(std::string* o, const void* p, size_t n) { o->append((const char*)p, n); }
static void putU64(std::string* o, uint64_t v) { put(o, &v, 8); }
static void putVec(std::string* o, const std::vector<double>& v) {
  putU64(o, v.size());
  if (!v.empty()) put(o, v.data(), 8 * v.size());
}
static void putMesh(std::string* o, const PanelMesh& p) {
  putVec(o, p.vert);
  putU64(o, p.face.size());
  if (!p.face.empty()) put(o, p.face.data(), sizeof(int) * p.face.size());
}

std::string radCacheDir(const std::string& entry) {
  std::string d = entry;
  const char* env = std::getenv(kRadCacheEnv);
  if (d.empty() && env && *env) d = env;
  if (d == "off") return "";
  if (!d.empty()) return d;
  const char* x = std::getenv("XDG_CACHE_HOME");
  if (x && *x == '/') return std::string(x) + "/mjbuoy";
  const char* h = std::getenv("HOME");
  if (h && *h) return std::string(h) + "/.cache/mjbuoy";
  return "";
}

std::string radCacheKey(const PanelMesh& body, const PanelMesh& lid,
                        const std::vector<double>& omega, const std::vector<double>& heading,
                        const HydroCoef& in) {
  std::string k;
  uint32_t v = kPanelSolverVersion, isz = sizeof(int);
  put(&k, &v, 4);
  put(&k, &isz, 4);
  put(&k, &in.rho, 8);
  put(&k, &in.g, 8);
  put(&k, &in.depth, 8);
  put(&k, in.ref, 24);
  putVec(&k, omega);
  putVec(&k, heading);
  putMesh(&k, body);
  putMesh(&k, lid);
  return k;
}

std::string radCachePath(const std::string& dir, const std::string& key) {
  char name[40];
  std::snprintf(name, sizeof name, "/panel-%016llx.mjbrad", (unsigned long long)fnv(key));
  return dir + name;
}

// the coefficients' bytes
static std::string payload(const HydroCoef& c) {
  std::string o;
  put(&o, c.ref, 24);
  put(&o, &c.rho, 8);
  put(&o, &c.g, 8);
  put(&o, &c.depth, 8);
  put(&o, c.Ainf, 8 * 36);
  for (const std::vector<double>* v : {&c.omega, &c.A, &c.B, &c.heading, &c.Xre, &c.Xim,
                                       &c.FKre, &c.FKim})
    putVec(&o, *v);
  return o;
}

// bounds-checked reader of a byte string
struct Reader {
  const std::string& s;
  size_t at = 0;
  bool ok = true;
  bool get(void* p, size_t n) {
    if (!ok || n > s.size() - at) return ok = false;
    std::memcpy(p, s.data() + at, n);
    at += n;
    return true;
  }
  bool getVec(std::vector<double>* v) {
    uint64_t n = 0;
    if (!get(&n, 8) || n > (s.size() - at) / 8) return ok = false;
    v->resize(n);
    return !n || get(v->data(), 8 * n);
  }
};

// parse the coefficients' bytes, with their sizes and values checked
static bool unpack(const std::string& s, HydroCoef* c) {
  Reader r{s};
  r.get(c->ref, 24), r.get(&c->rho, 8), r.get(&c->g, 8), r.get(&c->depth, 8);
  r.get(c->Ainf, 8 * 36);
  for (std::vector<double>* v : {&c->omega, &c->A, &c->B, &c->heading, &c->Xre, &c->Xim,
                                 &c->FKre, &c->FKim})
    r.getVec(v);
  if (!r.ok || r.at != s.size()) return false;
  size_t nw = c->omega.size(), nx = 6 * nw * c->heading.size();
  if (c->A.size() != 36 * nw || c->B.size() != 36 * nw || c->Xre.size() != nx ||
      c->Xim.size() != nx || c->FKre.size() != nx || c->FKim.size() != nx)
    return false;
  auto fin = [](const double* x, size_t n) {
    for (size_t i = 0; i < n; i++)
      if (!std::isfinite(x[i])) return false;
    return true;
  };
  if (!fin(c->ref, 3) || !fin(&c->rho, 1) || !fin(&c->g, 1) || !fin(&c->depth, 1) ||
      !fin(c->Ainf, 36))
    return false;
  for (const std::vector<double>* v : {&c->omega, &c->A, &c->B, &c->heading, &c->Xre, &c->Xim,
                                       &c->FKre, &c->FKim})
    if (!fin(v->data(), v->size())) return false;
  return true;
}

// the whole file; false if it cannot be read (or is too large to be ours)
static bool slurp(const std::string& path, std::string* s) {
  FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return false;
  bool ok = std::fseek(f, 0, SEEK_END) == 0;
  long n = ok ? std::ftell(f) : -1;
  ok = ok && n >= 0 && (uint64_t)n <= kMaxFile && std::fseek(f, 0, SEEK_SET) == 0;
  if (ok) {
    s->resize(n);
    ok = !n || std::fread(&(*s)[0], 1, n, f) == (size_t)n;
  }
  std::fclose(f);
  return ok;
}

static bool hasMagic(const std::string& s) {
  return s.size() >= 8 && !std::memcmp(s.data(), kMagic, 8);
}

bool radCacheLoad(const std::string& dir, const std::string& key, HydroCoef* c,
                  std::string* note) {
  note->clear();
  std::string path = radCachePath(dir, key), s;
  struct stat st;
  if (::stat(path.c_str(), &st) != 0) return false;  // plain miss
  if (!S_ISREG(st.st_mode) || !slurp(path, &s) || !hasMagic(s)) {
    *note = "radiation cache: " + path + " is not an mjbuoy cache file; left alone, "
            "coefficients computed";
    return false;
  }
  const std::string bad = "radiation cache: " + path + " ";
  if (s.size() < 8 + 8 + 8 + 8 + 8) {
    *note = bad + "is truncated; recomputed";
    return false;
  }
  uint64_t sum;
  std::memcpy(&sum, s.data() + s.size() - 8, 8);
  std::string body = s.substr(0, s.size() - 8);
  if (fnv(body) != sum) {
    *note = bad + "fails its checksum (corrupt or truncated); recomputed";
    return false;
  }
  Reader r{body};
  char mg[8];
  uint32_t fmt = 0, ver = 0;
  r.get(mg, 8), r.get(&fmt, 4), r.get(&ver, 4);
  if (fmt != kFormat || ver != kPanelSolverVersion) {
    *note = bad + "is of format " + std::to_string(fmt) + ", solver " + std::to_string(ver) +
            " (this library: " + std::to_string(kFormat) + ", " +
            std::to_string(kPanelSolverVersion) + "); recomputed";
    return false;
  }
  uint64_t nk = 0, np = 0;
  r.get(&nk, 8);
  if (!r.ok || nk > body.size() - r.at || body.compare(r.at, nk, key) != 0) {
    *note = bad + "holds another hull or settings (hash collision); recomputed";
    return false;
  }
  r.at += nk;
  r.get(&np, 8);
  if (!r.ok || np != body.size() - r.at) {
    *note = bad + "is malformed; recomputed";
    return false;
  }
  HydroCoef t;
  if (!unpack(body.substr(r.at), &t)) {
    *note = bad + "holds malformed or non-finite coefficients; recomputed";
    return false;
  }
  *c = std::move(t);
  return true;
}

std::string radCacheCheck(const PanelMesh& body, const std::vector<double>& omega,
                          const std::vector<double>& heading, const HydroCoef& in,
                          const HydroCoef& c) {
  char b[300];
  if (c.omega != omega) {
    std::snprintf(b, sizeof b, "holds %zu frequencies from %g rad/s where its key asks %zu from "
                  "%g rad/s", c.omega.size(), c.omega.empty() ? 0.0 : c.omega[0], omega.size(),
                  omega.empty() ? 0.0 : omega[0]);
    return b;
  }
  if (c.heading != heading) return "holds other headings than its key asks";
  if (c.rho != in.rho || c.g != in.g || c.depth != in.depth)
    return "holds another density, gravity or depth than its key asks";
  if (c.ref[0] != in.ref[0] || c.ref[1] != in.ref[1] || c.ref[2] != in.ref[2]) {
    std::snprintf(b, sizeof b, "holds the reference point (%g, %g, %g) m where its key asks "
                  "(%g, %g, %g) m", c.ref[0], c.ref[1], c.ref[2], in.ref[0], in.ref[1], in.ref[2]);
    return b;
  }
  const size_t nw = omega.size(), nx = 6 * nw * heading.size();
  if (c.A.size() != 36 * nw || c.B.size() != 36 * nw || c.Xre.size() != nx ||
      c.Xim.size() != nx || c.FKre.size() != nx || c.FKim.size() != nx)
    return "holds arrays of other sizes than its frequencies and headings";
  // the body's size: its farthest vertex from ref (at least 1 mm)
  double L = 1e-3;
  for (size_t v = 0; v + 2 < body.vert.size(); v += 3)
    L = std::max(L, std::hypot(std::hypot(body.vert[v] - in.ref[0], body.vert[v + 1] - in.ref[1]),
                               body.vert[v + 2] - in.ref[2]));
  const double kMargin = 1e3, m0 = in.rho * L * L * L;
  auto scale = [&](int i, int j) { return m0 * (i >= 3 ? L : 1) * (j >= 3 ? L : 1); };
  auto over = [&](double v, double lim) { return !std::isfinite(v) || std::fabs(v) > kMargin * lim; };
  for (int i = 0; i < 6; i++)
    for (int j = 0; j < 6; j++) {
      bool bad = over(c.Ainf[6 * i + j], scale(i, j));
      for (size_t w = 0; w < nw && !bad; w++)
        bad = over(c.A[36 * w + 6 * i + j], scale(i, j)) ||
              over(c.B[36 * w + 6 * i + j], omega[w] * scale(i, j));
      if (bad) {
        std::snprintf(b, sizeof b, "holds an added mass or damping (entry %d%d) beyond %g times "
                      "what a body %.3g m in size can have", i + 1, j + 1, kMargin, L);
        return b;
      }
    }
  for (size_t k = 0; k < nx; k++) {
    const double lim = in.rho * in.g * L * L * (k % 6 >= 3 ? L : 1);
    if (over(c.Xre[k], lim) || over(c.Xim[k], lim) || over(c.FKre[k], lim) || over(c.FKim[k], lim)) {
      std::snprintf(b, sizeof b, "holds an exciting force beyond %g times what a body %.3g m in "
                    "size can have", kMargin, L);
      return b;
    }
  }
  return "";
}

// mkdir -p; false with errno set
static bool makeDirs(const std::string& dir) {
  for (size_t i = 1; i <= dir.size(); i++) {
    if (i < dir.size() && dir[i] != '/') continue;
    std::string p = dir.substr(0, i);
    if (::mkdir(p.c_str(), 0755) != 0 && errno != EEXIST) return false;
  }
  struct stat st;
  if (::stat(dir.c_str(), &st) != 0) return false;
  if (!S_ISDIR(st.st_mode)) return errno = ENOTDIR, false;
  return true;
}

bool radCacheStore(const std::string& dir, const std::string& key, const HydroCoef& c,
                   std::string* note) {
  note->clear();
  std::string path = radCachePath(dir, key), old;
  const std::string cant = "radiation cache: cannot write " + path + ": ";
  struct stat st;
  if (::lstat(path.c_str(), &st) == 0 &&
      (!S_ISREG(st.st_mode) || !slurp(path, &old) || !hasMagic(old))) {
    *note = "radiation cache: " + path + " exists and is not an mjbuoy cache file; left "
            "alone (nothing cached)";
    return false;
  }
  if (!makeDirs(dir)) {
    *note = "radiation cache: cannot make the directory " + dir + ": " + std::strerror(errno) +
            " (nothing cached; set mjbuoy.radiation.cache or " + kRadCacheEnv +
            " to a writable directory, or to off)";
    return false;
  }
  std::string s(kMagic, 8);
  uint32_t fmt = kFormat, ver = kPanelSolverVersion;
  put(&s, &fmt, 4);
  put(&s, &ver, 4);
  putU64(&s, key.size());
  s += key;
  std::string p = payload(c);
  putU64(&s, p.size());
  s += p;
  putU64(&s, fnv(s));
  // a temporary file beside the target, renamed into place when complete:
  // a reader (another process attaching) sees no file or the whole file
  std::string tmp = dir + "/.panel-XXXXXX";
  std::vector<char> buf(tmp.begin(), tmp.end());
  buf.push_back(0);
  int fd = ::mkstemp(buf.data());
  if (fd < 0) {
    *note = cant + std::strerror(errno) + " (nothing cached)";
    return false;
  }
  tmp = buf.data();
  ::fchmod(fd, 0644);
  size_t done = 0;
  while (done < s.size()) {
    ssize_t w = ::write(fd, s.data() + done, s.size() - done);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) break;
    done += w;
  }
  int werr = done == s.size() ? 0 : errno ? errno : EIO;
  if (::close(fd) != 0 && !werr) werr = errno;
  if (!werr && ::rename(tmp.c_str(), path.c_str()) != 0) werr = errno;
  if (werr) {
    ::unlink(tmp.c_str());
    *note = cant + std::strerror(werr) + " (nothing cached)";
    return false;
  }
  return true;
}

}  // namespace mjb
