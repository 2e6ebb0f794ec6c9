// snell_bench_report: writes docs/benchmarks.md from one `bench` run (see
// benchmarks/run_bench.cmake): the Google Benchmark JSON of snell_bench and
// snell_bench_functions, the lab's table.json per size, and the run record
// (date, load averages, step times). Usage:
//   snell_bench_report --bench B.json --functions F.json [--lab table.json ...] --run run.txt --out report.md
// Exit 0, or 1 naming the file that is missing or malformed.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using nlohmann::json;

json readJson(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  try {
    return json::parse(in);
  } catch (const json::exception& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
}

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// 6.90 M, 534 k, 812
std::string rate(double v) {
  if (!(v > 0.0)) return "-";
  if (v >= 1e9) return fmt("%.2f G", v / 1e9);
  if (v >= 1e6) return fmt("%.2f M", v / 1e6);
  if (v >= 1e3) return fmt("%.0f k", v / 1e3);
  return fmt("%.0f", v);
}
std::string ns(double itemsPerSecond) { return itemsPerSecond > 0.0 ? fmt("%.0f", 1e9 / itemsPerSecond) : "-"; }
std::string ratio(double v) { return std::isfinite(v) && v > 0.0 ? fmt("%.2fx", v) : "-"; }

// The benchmarks of one Google Benchmark JSON file, by name (run_name): with
// repetitions, the median repetition (aggregate "median") and the coefficient
// of variation of the measured time over the repetitions (aggregate "cv");
// without, the single run.
class Results {
 public:
  Results() = default;
  explicit Results(const json& j) : context_(j.value("context", json::object())) {
    bool aggregates = false;
    for (const json& b : j.at("benchmarks")) aggregates = aggregates || b.value("run_type", "") == "aggregate";
    for (const json& b : j.at("benchmarks")) {
      const std::string name = b.value("run_name", b.at("name").get<std::string>());
      const std::string type = b.value("run_type", "iteration"), aggregate = b.value("aggregate_name", "");
      if (aggregates && type == "aggregate" && aggregate == "cv") {
        const bool real = name.find("/real_time") != std::string::npos;
        cv_[name] = b.value(real ? "real_time" : "cpu_time", 0.0);
      }
      if (aggregates ? (type != "aggregate" || aggregate != "median") : type != "iteration") continue;
      if (!byName_.count(name)) order_.push_back(name);
      byName_[name] = b;
    }
    // Registration order (the JSON's order is the random one of the repetitions).
    auto key = [this](const std::string& n) {
      const json& b = byName_.at(n);
      return std::make_pair(b.value("family_index", 0), b.value("per_family_instance_index", 0));
    };
    std::stable_sort(order_.begin(), order_.end(),
                     [&](const std::string& a, const std::string& b) { return key(a) < key(b); });
  }
  // name -> coefficient of variation of its time over the repetitions (empty without repetitions)
  const std::map<std::string, double>& cv() const { return cv_; }
  const json* find(const std::string& name) const {
    const auto it = byName_.find(name);
    return it == byName_.end() ? nullptr : &it->second;
  }
  double num(const std::string& name, const char* key) const {
    const json* b = find(name);
    if (!b || !b->contains(key) || !(*b)[key].is_number()) return std::nan("");
    return (*b)[key].get<double>();
  }
  double itemsPerSecond(const std::string& name) const { return num(name, "items_per_second"); }
  const std::vector<std::string>& order() const { return order_; }
  const json& context() const { return context_; }

 private:
  json context_;
  std::map<std::string, json> byName_;
  std::map<std::string, double> cv_;
  std::vector<std::string> order_;
};

struct Run {
  std::map<std::string, std::string> values;   // date, min_time, load_start, load_end
  std::string value(const std::string& key) const {
    const auto it = values.find(key);
    return it == values.end() ? "?" : it->second;
  }
  std::vector<std::pair<std::string, int>> steps;  // name, seconds
  std::map<std::string, std::string> loadAfter;
};

Run readRun(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  Run r;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string key, rest;
    s >> key;
    std::getline(s >> std::ws, rest);
    if (key == "step") {
      std::istringstream t(rest);
      std::string name;
      int seconds = 0;
      t >> name >> seconds;
      r.steps.emplace_back(name, seconds);
    } else if (key == "load_after") {
      std::istringstream t(rest);
      std::string name, avg;
      t >> name;
      std::getline(t >> std::ws, avg);
      r.loadAfter[name] = avg;
    } else if (!key.empty()) {
      r.values[key] = rest;
    }
  }
  return r;
}

std::string firstLineWith(const std::string& path, const std::string& key) {
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(key, 0) == 0) {
      const std::size_t colon = line.find_first_of(":=");
      if (colon == std::string::npos) return line;
      std::string v = line.substr(colon + 1);
      v.erase(0, v.find_first_not_of(" \t\""));
      while (!v.empty() && (v.back() == '"' || v.back() == ' ')) v.pop_back();
      return v;
    }
  return "unknown";
}

std::string machine(const Results& bench, const Results& functions, const Run& run) {
  const json& c = bench.context();
  std::string caches;
  for (const json& k : c.value("caches", json::array())) {
    if (!caches.empty()) caches += ", ";
    const int level = k.value("level", 0);
    const std::string type = k.value("type", "");
    const double size = k.value("size", 0.0);
    caches += "L" + std::to_string(level) + (type == "Data" ? "d" : type == "Instruction" ? "i" : "") + " " +
              (size >= 1048576 ? fmt("%.0f MiB", size / 1048576.0) : fmt("%.0f KiB", size / 1024.0));
    const int sharing = k.value("num_sharing", 0);
    if (sharing > 1) caches += " (shared by " + std::to_string(sharing) + ")";
  }
  std::string s;
  s += "- **CPU**: " + firstLineWith("/proc/cpuinfo", "model name") + ", " + std::to_string(c.value("num_cpus", 0)) +
       " logical CPUs at " + fmt("%.0f MHz", c.value("mhz_per_cpu", 0.0)) + "; caches " + caches + "; memory " +
       firstLineWith("/proc/meminfo", "MemTotal") + ".\n";
  s += "- **System**: " + firstLineWith("/etc/os-release", "PRETTY_NAME") + ", " SNELL_BENCH_COMPILER ", snell built " +
       std::string(SNELL_BENCH_BUILD_TYPE) + " with `-ffp-contract=off` (as the tests)" +
       (std::string(SNELL_BENCH_ARCH_FLAGS).empty()
            ? std::string(", no -march")
            : ", snell_bench's sources with `" + std::string(SNELL_BENCH_ARCH_FLAGS) +
                  "` (docs/api.md, compile flags for tools; the function benchmarks run the parity cases' objects, "
                  "built with the tests' flags)") +
       ". Google Benchmark's library " +
       "reports itself as a " + c.value("library_build_type", std::string("?")) +
       " build (Debian's libbenchmark; that is the harness, not the code measured).\n";
  s += "- **Run**: " + run.value("date") + ", `--benchmark_min_time=" + run.value("min_time") + "`, " +
       run.value("repetitions") + " repetitions per benchmark in random order (`--benchmark_enable_random_"
       "interleaving`); every CPU figure is the median repetition.\n";
  std::vector<std::pair<double, std::string>> cvs;
  for (const Results* r : {&bench, &functions})
    for (const auto& [name, v] : r->cv()) cvs.emplace_back(v, name);
  if (!cvs.empty()) {
    std::sort(cvs.begin(), cvs.end());
    s += "- **Noise**: the time's coefficient of variation over the repetitions is " +
         fmt("%.0f %%", 100.0 * cvs[cvs.size() / 2].first) + " for the median benchmark, " +
         fmt("%.0f %%", 100.0 * cvs[cvs.size() * 9 / 10].first) + " at the 90th percentile and " +
         fmt("%.0f %%", 100.0 * cvs.back().first) + " at most (" + cvs.back().second + ").\n";
  }
  s += "- **Load** (1/5/15-minute load averages from /proc/loadavg; the machine was shared with other builds): " +
       run.value("load_start") + " at the start";
  for (const auto& [name, seconds] : run.steps) {
    const auto it = run.loadAfter.find(name);
    if (it != run.loadAfter.end()) s += "; " + it->second + " after " + name;
  }
  s += "; " + run.value("load_end") + " at the end. With more runnable threads than cores, absolute rates drop and the multi-threaded scaling is "
       "understated; ratios between benchmarks of the same run are the figures to read.\n";
  int total = 0;
  std::string steps;
  for (const auto& [name, seconds] : run.steps) {
    total += seconds;
    steps += (steps.empty() ? "" : ", ") + name + " " + std::to_string(seconds) + " s";
  }
  s += "- **Wall time**: " + std::to_string(total) + " s (" + steps + ").\n";
  return s;
}

// "BM_X/a/b" -> the part after the last '/', as a number ("256", "threads:2" -> 2).
double lastNumber(const std::string& name) {
  std::string tail = name.substr(name.rfind('/') + 1);
  const std::size_t colon = tail.rfind(':');
  if (colon != std::string::npos) tail = tail.substr(colon + 1);
  try {
    return std::stod(tail);
  } catch (...) {
    return std::nan("");
  }
}

std::string strategiesSection(const Results& b) {
  std::string s = "## Intersection strategies (CPU, single thread)\n\n";
  s += "Refracted rays through the sphere of `tests/support/depth_scenes.hpp` (`sphereBack`, 512x512 back-face "
       "depth buffer), one per pixel inside the silhouette, scan order. Sources: "
       "`benchmarks/intersect_plane_bench.cpp` (eta 1/1.5, every front-face pixel) and "
       "`benchmarks/intersect_search_bench.cpp` (eta 1/1.2; `error` = mean distance to the analytic hit, view-space "
       "units, radius 2.2). Cost ratio: time per ray over single sample's.\n\n";
  s += "| strategy | rays/s | ns/ray | cost ratio | fetches/ray | valid share |\n|---|---:|---:|---:|---:|---:|\n";
  const double single = b.itemsPerSecond("BM_SingleSample");
  const std::vector<std::pair<std::string, std::string>> plane = {
      {"BM_SingleSample", "single sample"},
      {"BM_PlaneNormal/0", "plane, normal-based, 0 refinements"},
      {"BM_PlaneNormal/1", "plane, normal-based, 1 refinement"},
      {"BM_PlaneNormal/2", "plane, normal-based, 2 refinements"},
      {"BM_PlaneDepth/0", "plane, depth-based (pyramid), 0"},
      {"BM_PlaneDepth/1", "plane, depth-based (pyramid), 1"},
      {"BM_PlaneDepth/2", "plane, depth-based (pyramid), 2"}};
  for (const auto& [name, label] : plane) {
    const double ips = b.itemsPerSecond(name);
    s += "| " + label + " | " + rate(ips) + " | " + ns(ips) + " | " + ratio(single / ips) + " | " +
         fmt("%.2f", b.num(name, "fetches/ray")) + " | " + fmt("%.3f", b.num(name, "valid")) + " |\n";
  }
  s += "\n| strategy | rays/s | ns/ray | cost ratio | fetches/ray | mean error | hit share |\n"
       "|---|---:|---:|---:|---:|---:|---:|\n";
  const std::vector<std::pair<std::string, std::string>> search = {
      {"BM_ConservativeBinarySearch5", "conservative binary search, 5 steps (DIR)"},
      {"BM_BinarySearch5", "binary search, 5 steps"},
      {"BM_LinearBinarySearch10x5", "linear 10 + binary 5"},
      {"BM_LinearMarch32x4", "linear march 32 + 4 bisections"},
      {"BM_DdaMarchStride1", "DDA march, stride 1"},
      {"BM_DdaMarchStride4", "DDA march, stride 4"}};
  for (const auto& [name, label] : search) {
    const double ips = b.itemsPerSecond(name);
    s += "| " + label + " | " + rate(ips) + " | " + ns(ips) + " | " + ratio(single / ips) + " | " +
         fmt("%.1f", b.num(name, "fetches")) + " | " + fmt("%.4f", b.num(name, "error")) + " | " +
         fmt("%.2f", b.num(name, "hitShare")) + " |\n";
  }
  return s + "\n";
}

std::string resolutionSection(const Results& b) {
  const std::vector<int> sizes = {256, 512, 1024, 2048};
  std::vector<std::string> strategies;
  for (const std::string& n : b.order())
    if (n.rfind("BM_Resolution/", 0) == 0) {
      const std::string mid = n.substr(14, n.rfind('/') - 14);
      if (std::find(strategies.begin(), strategies.end(), mid) == strategies.end()) strategies.push_back(mid);
    }
  std::string s = "## Cost against resolution (CPU, single thread)\n\n";
  s += "`benchmarks/resolution_bench.cpp`: the same world-space scene and refraction (sphereBack, eta 1/1.2, every "
       "pixel inside the silhouette) at N x N buffers. Fetches per ray (machine-independent, every 16th ray of the "
       "frame) stay flat for the constant-time strategies and grow with N for the DDA march over a fixed "
       "world-space length (5 units); the linear march's fixed view-space step count keeps its fetches flat. The "
       "time per ray is given relative to the same strategy at 256: above 1 where the buffers outgrow the caches "
       "(a 2048x2048 RGBA32F level is 64 MiB).\n\n";
  s += "| strategy | fetches/ray 256 | 512 | 1024 | 2048 | valid share 256 / 2048 |\n|---|---:|---:|---:|---:|---:|\n";
  for (const std::string& st : strategies) {
    s += "| " + st;
    for (int n : sizes) s += " | " + fmt("%.1f", b.num("BM_Resolution/" + st + "/" + std::to_string(n), "fetches"));
    s += " | " + fmt("%.3f", b.num("BM_Resolution/" + st + "/256", "valid")) + " / " +
         fmt("%.3f", b.num("BM_Resolution/" + st + "/2048", "valid")) + " |\n";
  }
  s += "\n| strategy | rays/s at 256 | time/ray 256 | 512 | 1024 | 2048 | cost vs single sample at 512 |\n"
       "|---|---:|---:|---:|---:|---:|---:|\n";
  const double single512 = b.itemsPerSecond("BM_Resolution/single/512");
  for (const std::string& st : strategies) {
    const double base = b.itemsPerSecond("BM_Resolution/" + st + "/256");
    s += "| " + st + " | " + rate(base);
    for (int n : sizes) s += " | " + ratio(base / b.itemsPerSecond("BM_Resolution/" + st + "/" + std::to_string(n)));
    s += " | " + ratio(single512 / b.itemsPerSecond("BM_Resolution/" + st + "/512")) + " |\n";
  }
  return s + "\n";
}

std::string stepsTable(const Results& b, const std::string& prefix, const std::string& knob) {
  std::vector<std::string> names;
  for (const std::string& n : b.order())
    if (n.rfind(prefix + "/", 0) == 0) names.push_back(n);
  std::string s = "| " + knob + " | rays/s | time/ray vs first row | fetches/ray | mean error | hit share |\n"
                  "|---:|---:|---:|---:|---:|---:|\n";
  if (names.empty()) return s;
  const double base = b.itemsPerSecond(names.front());
  for (const std::string& n : names) {
    const double ips = b.itemsPerSecond(n);
    s += "| " + fmt("%.0f", lastNumber(n)) + " | " + rate(ips) + " | " + ratio(base / ips) + " | " +
         fmt("%.1f", b.num(n, "fetches")) + " | " + fmt("%.4f", b.num(n, "error")) + " | " +
         fmt("%.2f", b.num(n, "hitShare")) + " |\n";
  }
  return s;
}

std::string stepsSection(const Results& b) {
  std::string s = "## Cost against step count (CPU, single thread, 512x512)\n\n";
  s += "The marches' knob, on the rays of the strategies table (eta 1/1.2). Time and fetches grow linearly with "
       "the steps taken; the constant-time strategies have no such knob. Linear march: view-space steps over 5 "
       "units, then 4 bisections.\n\n";
  s += stepsTable(b, "BM_LinearMarchSteps", "steps");
  s += "\nDDA march, stride 1, step cap (a ray needing more pixels than the cap stops short):\n\n";
  s += stepsTable(b, "BM_DdaMarchMaxSteps", "max steps");
  s += "\nDDA march, stride (pixels per step; cap 1024):\n\n";
  s += stepsTable(b, "BM_DdaMarchStride", "stride");
  return s + "\n";
}

std::string techniqueSection(const Results& b) {
  const std::string prefix = "BM_TwoInterface/";
  std::vector<std::string> names;  // registration order = the technique table's
  for (const std::string& n : b.order())
    if (n.rfind(prefix, 0) == 0) names.push_back(n);
  std::string s = "## Whole technique per row of the technique table (CPU, single thread)\n\n";
  s += "`benchmarks/technique_bench.cpp`: `snellTwoInterfaceRefraction` (both interfaces, exit into the opaque "
       "scene), glass sphere in front of a painting, 256x256 buffers, every second pixel of the sphere in each "
       "direction. Cost ratio: time per pixel over single sample's.\n\n";
  s += "| technique | pixels/s | ns/pixel | cost ratio | fetches/px |\n|---|---:|---:|---:|---:|\n";
  const auto single = std::find(names.begin(), names.end(), prefix + "single");
  const double unit = single != names.end() ? b.itemsPerSecond(*single) : std::nan("");
  for (const std::string& n : names) {
    const double ips = b.itemsPerSecond(n);
    s += "| " + n.substr(prefix.size()) + " | " + rate(ips) + " | " + ns(ips) + " | " + ratio(unit / ips) + " | " +
         fmt("%.1f", b.num(n, "fetches/px")) + " |\n";
  }
  return s + "\n";
}

std::string threadsSection(const Results& b) {
  // prefix -> thread count -> name
  std::map<std::string, std::map<int, std::string>> groups;
  std::vector<std::string> order;
  for (const std::string& n : b.order()) {
    if (n.rfind("BM_BakeWymanDn/", 0) != 0 && n.rfind("BM_RefractFrame/", 0) != 0) continue;
    const std::size_t t = n.find("/threads:");
    if (t == std::string::npos) continue;
    const std::string prefix = n.substr(0, t);
    const int threads = std::stoi(n.substr(t + 9));
    if (!groups.count(prefix)) order.push_back(prefix);
    groups[prefix][threads] = n;
  }
  int maxThreads = 1;
  for (const auto& [p, g] : groups) maxThreads = std::max(maxThreads, g.rbegin()->first);
  std::string s = "## Multi-threaded (CPU, the tool use case)\n\n";
  s += "`benchmarks/threads_bench.cpp`: the work split over explicit `std::thread`s (chunks or rows through an "
       "atomic counter), wall-clock time. Scaling: throughput over the 1-thread throughput (ideal: the thread "
       "count, at most the number of idle cores). CPU-time bound: the calling thread's CPU time with 1 thread over "
       "that with T threads (it does its share of the work, and for d_N the BVH build's serial part); other processes' "
       "load does not move it, so it shows how evenly the work splits and bounds the wall-clock scaling on idle "
       "cores from above.\n\n";
  s += "Wyman's d_N for every vertex (`include/snell/wyman_dn.hpp`: the BVH built once, its top levels on the T "
       "threads, and counted; the vertices' rays in parallel). bvh share: the build's share of the calling thread's "
       "CPU time.\n\n";
  std::string head = "| mesh | vertices | triangles | bvh share | vertices/s, 1 thread", rule = "|---|---:|---:|---:|---:";
  for (int t = 2; t <= maxThreads; t *= 2) {
    head += " | " + std::to_string(t) + " threads | scaling | CPU-time bound";
    rule += "|---:|---:|---:";
  }
  s += head + " |\n" + rule + "|\n";
  auto rows = [&](const std::string& kind, bool mesh) {
    std::string r;
    for (const std::string& p : order) {
      if (p.rfind(kind, 0) != 0) continue;
      const std::map<int, std::string>& g = groups[p];
      if (!g.count(1)) continue;
      const double one = b.itemsPerSecond(g.at(1));
      r += "| " + p.substr(kind.size());
      if (mesh)
        r += " | " + fmt("%.0f", b.num(g.at(1), "vertices")) + " | " + fmt("%.0f", b.num(g.at(1), "triangles")) + " | " +
             fmt("%.2f", b.num(g.at(1), "bvh_share"));
      else
        r += " | " + fmt("%.0f", b.num(g.at(1), "pixels")) + " | " +
             fmt("%.0f ms", b.num(g.at(1), "real_time"));
      r += " | " + rate(one);
      for (int t = 2; t <= maxThreads; t *= 2) {
        const double ips = g.count(t) ? b.itemsPerSecond(g.at(t)) : std::nan("");
        const double cpuBound = g.count(t) ? b.num(g.at(1), "cpu_time") / b.num(g.at(t), "cpu_time") : std::nan("");
        r += " | " + rate(ips) + " | " + ratio(ips / one) + " | " + ratio(cpuBound);
      }
      r += " |\n";
    }
    return r;
  };
  s += rows("BM_BakeWymanDn/", true);
  s += "\nA 512x512 frame of `snellTwoInterfaceRefraction` per technique (the sphere's pixels of "
       "`tests/support/technique_scene.hpp`).\n\n";
  head = "| technique | sphere pixels | frame, 1 thread | pixels/s, 1 thread";
  rule = "|---|---:|---:|---:";
  for (int t = 2; t <= maxThreads; t *= 2) {
    head += " | " + std::to_string(t) + " threads | scaling | CPU-time bound";
    rule += "|---:|---:|---:";
  }
  s += head + " |\n" + rule + "|\n";
  s += rows("BM_RefractFrame/", false);
  return s + "\n";
}

std::string labSection(const std::vector<json>& labs, const Run& run) {
  if (labs.empty()) return "";
  std::string s = "## GL: the lab per resolution (Mesa llvmpipe)\n\n";
  s += "`snell-lab --size NxN --frames F` on the bundled bunny scene (every technique, the refraction pass timed "
       "with glFinish + steady clock, median of F frames, techniques interleaved; see examples/lab/README.md). "
       "GL: " + labs.front().value("gpu", std::string("?")) + ". The lab's DDA march stops after 256 steps per "
       "interface, the linear march takes 32 view-space steps. A software rasterizer on a shared 2-core machine: "
       "read the ratios, not the milliseconds.\n\n";
  std::vector<std::string> techniques, labels;
  for (const json& t : labs.front().at("techniques")) {
    techniques.push_back(t.at("technique").get<std::string>());
    labels.push_back(t.value("label", techniques.back()));
  }
  auto row = [](const json& lab, const std::string& name) -> const json* {
    for (const json& t : lab.at("techniques"))
      if (t.at("technique") == name) return &t;
    return nullptr;
  };
  auto header = [&](const std::string& first) {
    std::string h = "| " + first, r = "|---";
    for (const json& l : labs) {
      h += " | " + std::to_string(l.value("width", 0)) + "x" + std::to_string(l.value("height", 0));
      r += "|---:";
    }
    return h + " |\n" + r + "|\n";
  };
  s += "Time of the refraction pass relative to single sample at the same resolution:\n\n" + header("technique");
  for (std::size_t i = 0; i < techniques.size(); ++i) {
    s += "| " + labels[i];
    for (const json& l : labs) {
      const json* t = row(l, techniques[i]);
      s += " | " + (t ? ratio(t->value("time_ratio_to_single", 0.0)) : "-");
    }
    s += " |\n";
  }
  s += "\nTime of the refraction pass relative to the same technique at " + std::to_string(labs.front().value("width", 0)) +
       " (the object's pixel count grows 4x per step: ";
  for (std::size_t i = 0; i < labs.size(); ++i)
    s += (i ? ", " : "") + std::to_string(labs[i].value("object_pixels", 0));
  s += " object pixels; constant cost per pixel gives the pixel ratio):\n\n" + header("technique");
  s += "| object pixels";
  const double basePixels = labs.front().value("object_pixels", 0.0);
  for (const json& l : labs) s += " | " + ratio(l.value("object_pixels", 0.0) / basePixels);
  s += " |\n";
  for (std::size_t i = 0; i < techniques.size(); ++i) {
    const json* base = row(labs.front(), techniques[i]);
    const double b0 = base ? base->value("time_ms_median", 0.0) : 0.0;
    s += "| " + labels[i];
    for (const json& l : labs) {
      const json* t = row(l, techniques[i]);
      s += " | " + (t && b0 > 0.0 ? ratio(t->value("time_ms_median", 0.0) / b0) : "-");
    }
    s += " |\n";
  }
  s += "\nTexel fetches per object pixel (GPU counters, both interfaces):\n\n" + header("technique");
  for (std::size_t i = 0; i < techniques.size(); ++i) {
    s += "| " + labels[i];
    for (const json& l : labs) {
      const json* t = row(l, techniques[i]);
      s += " | " + (t ? fmt("%.1f", t->value("fetches_per_pixel", 0.0)) : "-");
    }
    s += " |\n";
  }
  s += "\nSingle sample's refraction pass took";
  for (std::size_t i = 0; i < labs.size(); ++i) {
    const json* t = row(labs[i], "single");
    s += (i ? ", " : " ") + (t ? fmt("%.1f ms", t->value("time_ms_median", 0.0)) : "-") + " at " +
         std::to_string(labs[i].value("width", 0));
  }
  s += ". Frames per size and the lab's wall time (with its Embree ground truth, the C++ comparison and the "
       "pictures, which the lab always does):";
  for (const json& l : labs) {
    const std::string step = "lab_" + std::to_string(l.value("width", 0));
    int seconds = -1;
    for (const auto& [name, sec] : run.steps)
      if (name == step) seconds = sec;
    s += " " + std::to_string(l.value("width", 0)) + ": " + std::to_string(l.value("frames", 0)) + " frames, " +
         std::to_string(seconds) + " s;";
  }
  s.back() = '.';
  return s + "\n\n";
}

// A few headline ratios computed from the tables below.
std::string summarySection(const Results& b, const std::vector<json>& labs) {
  std::string s = "## Summary (ratios from this run)\n\n";
  double worst = 1.0;  // the 2048/256 fetch ratio farthest from 1
  std::string worstName;
  std::vector<std::string> strategies;
  for (const std::string& n : b.order())
    if (n.rfind("BM_Resolution/", 0) == 0 && n.size() > 5 && n.substr(n.size() - 4) == "/256")
      strategies.push_back(n.substr(14, n.size() - 18));
  for (const std::string& st : strategies) {
    if (st.rfind("dda", 0) == 0) continue;
    const double r = b.num("BM_Resolution/" + st + "/2048", "fetches") / b.num("BM_Resolution/" + st + "/256", "fetches");
    if (worstName.empty() || std::fabs(r - 1.0) > std::fabs(worst - 1.0)) {
      worst = r;
      worstName = st;
    }
  }
  if (!worstName.empty())
    s += "- CPU, 256 -> 2048 buffers of the same scene, one ray per pixel: fetches per ray of every strategy but the DDA march "
         "change by at most " + fmt("%.0f %%", 100.0 * std::fabs(worst - 1.0)) + " (" + worstName + "); the DDA "
         "march (stride 1) does " + ratio(b.num("BM_Resolution/dda-stride-1/2048", "fetches") /
                                          b.num("BM_Resolution/dda-stride-1/256", "fetches")) +
         " the fetches and takes " + ratio(b.itemsPerSecond("BM_Resolution/dda-stride-1/256") /
                                           b.itemsPerSecond("BM_Resolution/dda-stride-1/2048")) +
         " the time per ray; single sample's time per ray is " +
         ratio(b.itemsPerSecond("BM_Resolution/single/256") / b.itemsPerSecond("BM_Resolution/single/2048")) + " its 256 value.\n";
  if (labs.size() >= 2) {
    auto find = [](const json& lab, const char* name) -> const json* {
      for (const json& t : lab.at("techniques"))
        if (t.at("technique") == name) return &t;
      return nullptr;
    };
    const json *d0 = find(labs.front(), "dda"), *d1 = find(labs.back(), "dda"), *p0 = find(labs.front(), "plane-normal-1"),
               *p1 = find(labs.back(), "plane-normal-1");
    if (d0 && d1 && p0 && p1)
      s += "- GL, " + std::to_string(labs.front().value("width", 0)) + " -> " +
           std::to_string(labs.back().value("width", 0)) + ": the DDA march costs " +
           ratio(d0->value("time_ratio_to_single", 0.0)) + " -> " + ratio(d1->value("time_ratio_to_single", 0.0)) +
           " single sample's time (fetches/px " + fmt("%.0f", d0->value("fetches_per_pixel", 0.0)) + " -> " +
           fmt("%.0f", d1->value("fetches_per_pixel", 0.0)) + "); the normal-based plane (1 iteration) " +
           ratio(p0->value("time_ratio_to_single", 0.0)) + " -> " + ratio(p1->value("time_ratio_to_single", 0.0)) +
           " at a constant " + fmt("%.1f", p1->value("fetches_per_pixel", 0.0)) + " fetches/px.\n";
  }
  double lo = 1e300, hi = 0.0, cpuLo = 1e300, cpuHi = 0.0;
  for (const std::string& n : b.order()) {
    const std::size_t t = n.find("/threads:2/");
    if (t == std::string::npos) continue;
    const std::string one = n.substr(0, t) + "/threads:1/real_time";
    const double r = b.itemsPerSecond(n) / b.itemsPerSecond(one), c = b.num(one, "cpu_time") / b.num(n, "cpu_time");
    if (!std::isfinite(r) || !std::isfinite(c)) continue;
    lo = std::min(lo, r);
    hi = std::max(hi, r);
    cpuLo = std::min(cpuLo, c);
    cpuHi = std::max(cpuHi, c);
  }
  if (hi > 0.0)
    s += "- CPU, 2 threads vs 1 (d_N baking, full-frame refraction): " + ratio(lo) + " to " + ratio(hi) +
         " the wall-clock throughput on this shared machine (load above); CPU-time bound " + ratio(cpuLo) + " to " +
         ratio(cpuHi) + " (see the multi-threaded section).\n";
  return s + "\n";
}

std::string functionsSection(const Results& f) {
  std::string s = "## Every public function (CPU, single thread)\n\n";
  s += "`benchmarks/functions/functions_bench.cpp` (`snell_bench_functions`): one benchmark per parity case "
       "(`tests/parity/*_cases.cpp`), cycling through the case's own 10-12k inputs (realistic ranges plus a few per "
       "cent of edge and hostile values). Each call goes through the case entry (unpack four vec4s, call, pack) and "
       "a std::function: a few ns that dominate the cheapest functions, so compare those by order of magnitude. "
       "Texture-reading functions read the case's small textures.\n\n";
  s += "| family | function | calls/s | ns/call |\n|---|---|---:|---:|\n";
  for (const std::string& n : f.order()) {
    if (n.rfind("BM_Function/", 0) != 0) continue;
    const std::string rest = n.substr(12);
    const std::size_t slash = rest.find('/');
    const double ips = f.itemsPerSecond(n);
    s += "| " + rest.substr(0, slash) + " | `" + rest.substr(slash + 1) + "` | " + rate(ips) + " | " +
         (ips > 0.0 ? fmt(1e9 / ips < 10.0 ? "%.1f" : "%.0f", 1e9 / ips) : "-") + " |\n";
  }
  return s + "\n";
}

}  // namespace

int main(int argc, char** argv) {
  std::string benchPath, functionsPath, runPath, outPath;
  std::vector<std::string> labPaths;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (i + 1 >= argc) {
      std::fprintf(stderr, "snell_bench_report: %s needs a value\n", a.c_str());
      return 1;
    }
    const std::string v = argv[++i];
    if (a == "--bench") benchPath = v;
    else if (a == "--functions") functionsPath = v;
    else if (a == "--lab") labPaths.push_back(v);
    else if (a == "--run") runPath = v;
    else if (a == "--out") outPath = v;
    else {
      std::fprintf(stderr, "snell_bench_report: unknown option %s\n", a.c_str());
      return 1;
    }
  }
  if (benchPath.empty() || functionsPath.empty() || runPath.empty() || outPath.empty()) {
    std::fprintf(stderr,
                 "usage: snell_bench_report --bench B.json --functions F.json [--lab table.json ...] --run run.txt "
                 "--out report.md\n");
    return 1;
  }
  try {
    const Results bench(readJson(benchPath)), functions(readJson(functionsPath));
    std::vector<json> labs;
    for (const std::string& p : labPaths) labs.push_back(readJson(p));
    const Run run = readRun(runPath);

    std::string md = "# Benchmarks\n\n";
    md += "Generated by `cmake --build build --target bench` (`benchmarks/run_bench.cmake`, "
          "`benchmarks/report/bench_report.cpp`) from one run; do not edit by hand. CPU figures are the C++ build of "
          "the GLSL functions; GL figures come from the lab on Mesa llvmpipe. Nothing here is asserted by a test. "
          "Read ratios between rows of the same run: the absolute rates depend on the machine and its load. Fetch "
          "counts do not depend on the machine.\n\n";
    md += "## Machine and run\n\n" + machine(bench, functions, run) + "\n";
    md += summarySection(bench, labs);
    md += strategiesSection(bench);
    md += resolutionSection(bench);
    md += stepsSection(bench);
    md += techniqueSection(bench);
    md += threadsSection(bench);
    md += labSection(labs, run);
    md += functionsSection(functions);
    std::ofstream out(outPath);
    if (!out) throw std::runtime_error("cannot write " + outPath);
    out << md;
    if (!out) throw std::runtime_error("cannot write " + outPath);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "snell_bench_report: %s\n", e.what());
    return 1;
  }
  return 0;
}
