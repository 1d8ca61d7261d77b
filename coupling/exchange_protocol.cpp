#include "coupling/exchange_protocol.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <thread>

#include <fmt/format.h>

#include "dem/core/errors.hpp"

namespace fs = std::filesystem;

namespace icedem {
namespace {

std::string vec(const Eigen::Vector3d& v) { return fmt::format("{:.17g} {:.17g} {:.17g}", v.x(), v.y(), v.z()); }

std::string header(const char* kind) { return fmt::format("icedem-exchange {}\nkind {}\n", kExchangeVersion, kind); }

// a record's lines, checked for the versioned header, the kind and the final "end"
class Record {
 public:
  Record(const std::string& text, const std::string& file, const std::string& kind) : file_(file) {
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);) lines_.push_back(l);
    if (lines_.empty() || lines_[0].rfind("icedem-exchange ", 0) != 0)
      throw ProtocolError(fmt::format("{}:1: not an icedem exchange file (expected the header 'icedem-exchange {}')",
                                      file, kExchangeVersion));
    if (lines_[0] != fmt::format("icedem-exchange {}", kExchangeVersion))
      throw ProtocolError(fmt::format("{}:1: '{}': protocol version mismatch; this program speaks version {}", file,
                                      lines_[0], kExchangeVersion));
    if (lines_.back() != "end")
      throw ProtocolError(fmt::format("{}:{}: no final 'end' line: the file is truncated or half-written", file,
                                      lines_.size()));
    next_ = 1;
    const std::string k = field("kind");
    if (k != kind) throw ProtocolError(fmt::format("{}:2: kind '{}', expected '{}'", file, k, kind));
  }

  // "name value..." on the next line: the value part
  std::string field(const std::string& name) {
    const std::string& l = line();
    if (l.rfind(name + " ", 0) != 0)
      throw ProtocolError(fmt::format("{}:{}: expected '{} ...', found '{}'", file_, next_, name, l));
    return l.substr(name.size() + 1);
  }

  // `n` numbers from a string, or an error naming the line
  std::vector<double> numbers(const std::string& text, std::size_t n) {
    std::istringstream in(text);
    in.imbue(std::locale::classic());
    std::vector<double> v(n);
    for (double& x : v)
      if (!(in >> x)) throw ProtocolError(fmt::format("{}:{}: expected {} numbers in '{}'", file_, next_, n, text));
    std::string extra;
    if (in >> extra) throw ProtocolError(fmt::format("{}:{}: more than {} numbers in '{}'", file_, next_, n, text));
    return v;
  }

  std::string row() { return line(); }

  void finish() {
    if (next_ != lines_.size() - 1)
      throw ProtocolError(fmt::format("{}:{}: unexpected line '{}' before 'end'", file_, next_ + 1, lines_[next_]));
  }

 private:
  const std::string& line() {
    if (next_ + 1 >= lines_.size())
      throw ProtocolError(fmt::format("{}:{}: the record ends early", file_, next_ + 1));
    return lines_[next_++];
  }

  std::string file_;
  std::vector<std::string> lines_;
  std::size_t next_ = 0;
};

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

Eigen::Vector3d v3(const std::vector<double>& v, std::size_t at) { return {v[at], v[at + 1], v[at + 2]}; }

int count(Record& r, const std::string& name) {
  const std::vector<double> n = r.numbers(r.field(name), 1);
  if (n[0] < 0 || n[0] != std::floor(n[0])) throw ProtocolError(fmt::format("'{}' is not a count", n[0]));
  return static_cast<int>(n[0]);
}

}  // namespace

std::string format_hello(const ExchangeHello& h) {
  return header("hello") + fmt::format("role {}\nrun {}\ncase {}\nend\n", h.role, h.run, h.case_hash);
}

std::string format_request(const ExchangeRequest& r) {
  std::string s = header("request") + fmt::format("run {}\nstep {}\ntime {:.17g}\nstructure {} {}\n", r.run, r.step,
                                                  r.time, vec(r.structure_position), vec(r.structure_velocity));
  s += fmt::format("water {:.17g} {:.17g} {:.17g}\nfloes {}\n", r.density, r.drag_coefficient,
                   r.skin_friction_coefficient, r.floes.size());
  for (const ExchangeFloe& f : r.floes)
    s += fmt::format("{} {} {} {:.17g} {:.17g}\n", f.id, vec(f.position), vec(f.velocity), f.frontal_area, f.bottom_area);
  return s + "end\n";
}

std::string format_response(const ExchangeResponse& r) {
  std::string s = header("response") + fmt::format("run {}\nstep {}\nfloes {}\n", r.run, r.step, r.floes.size());
  for (const ExchangeDrag& d : r.floes) s += fmt::format("{} {} {}\n", d.id, vec(d.force), vec(d.water));
  return s + "end\n";
}

ExchangeHello parse_hello(const std::string& text, const std::string& file) {
  Record r(text, file, "hello");
  ExchangeHello h{r.field("role"), r.field("run"), r.field("case")};
  r.finish();
  return h;
}

ExchangeRequest parse_request(const std::string& text, const std::string& file) {
  Record r(text, file, "request");
  ExchangeRequest q;
  q.run = r.field("run");
  q.step = static_cast<long>(r.numbers(r.field("step"), 1)[0]);
  q.time = r.numbers(r.field("time"), 1)[0];
  const std::vector<double> s = r.numbers(r.field("structure"), 6);
  q.structure_position = v3(s, 0);
  q.structure_velocity = v3(s, 3);
  const std::vector<double> w = r.numbers(r.field("water"), 3);
  q.density = w[0];
  q.drag_coefficient = w[1];
  q.skin_friction_coefficient = w[2];
  const int n = count(r, "floes");
  for (int i = 0; i < n; ++i) {
    const std::vector<double> f = r.numbers(r.row(), 9);
    q.floes.push_back({static_cast<int>(f[0]), v3(f, 1), v3(f, 4), f[7], f[8]});
  }
  r.finish();
  return q;
}

ExchangeResponse parse_response(const std::string& text, const std::string& file) {
  Record r(text, file, "response");
  ExchangeResponse p;
  p.run = r.field("run");
  p.step = static_cast<long>(r.numbers(r.field("step"), 1)[0]);
  const int n = count(r, "floes");
  for (int i = 0; i < n; ++i) {
    const std::vector<double> d = r.numbers(r.row(), 7);
    p.floes.push_back({static_cast<int>(d[0]), v3(d, 1), v3(d, 4)});
  }
  r.finish();
  return p;
}

std::string request_name(long step) { return fmt::format("request.{:010d}", step); }
std::string response_name(long step) { return fmt::format("response.{:010d}", step); }

void write_atomic(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary);
    if (!(out << text) || !out.flush()) throw CouplingError(fmt::format("{}: cannot write", tmp));
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) throw CouplingError(fmt::format("{}: cannot rename to {} ({})", tmp, path, ec.message()));
}

namespace {

bool exchange_file(const std::string& name) {
  for (const char* prefix : {"request.", "response.", "dem.hello", "partner.hello", "stop"})
    if (name.rfind(prefix, 0) == 0) return true;
  return false;
}

std::string random_run_id() {
  std::random_device rd;
  return fmt::format("{:08x}{:08x}-{}", rd(), rd(), ::getpid());
}

}  // namespace

ExchangeChannel::ExchangeChannel(std::string dir, std::string case_hash, std::chrono::duration<double> timeout)
    : dir_(std::move(dir)), case_hash_(std::move(case_hash)), run_(random_run_id()), timeout_(timeout) {
  std::error_code ec;
  fs::create_directories(dir_, ec);
  if (ec) throw CouplingError(fmt::format("exchange directory {}: cannot create it ({})", dir_, ec.message()));
  for (const auto& e : fs::directory_iterator(dir_))  // an earlier run's files
    if (e.is_regular_file() && exchange_file(e.path().filename().string())) fs::remove(e.path());
  write_atomic((fs::path(dir_) / "dem.hello").string(), format_hello({"dem", run_, case_hash_}));
}

namespace {

// polls for `path` until the deadline; false on timeout
bool wait_for(const fs::path& path, std::chrono::steady_clock::time_point deadline) {
  auto pause = std::chrono::microseconds(200);
  while (!fs::exists(path)) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::microseconds(20000));
  }
  return true;
}

}  // namespace

void ExchangeChannel::wait_for_partner() {
  const fs::path hello = fs::path(dir_) / "partner.hello";
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::duration_cast<std::chrono::steady_clock::duration>(timeout_);
  while (true) {
    if (!wait_for(hello, deadline))
      throw CouplingError(fmt::format("no OpenFOAM partner: {} did not appear within {:.0f} s (coupling.timeout); "
                                      "is coupling/foam_partner.py running on {}?",
                                      hello.string(), timeout_.count(), dir_));
    const ExchangeHello h = parse_hello(read_text(hello), hello.string());
    if (h.run == run_ && h.role == "partner") {
      if (h.case_hash != case_hash_)
        throw CouplingError(fmt::format("{}: the partner loaded case {}, this run needs {}", hello.string(),
                                        h.case_hash, case_hash_));
      return;
    }
    refused_.push_back(fmt::format("{}: stale (run {}, this run is {})", hello.string(), h.run, run_));
    fs::remove(hello);
  }
}

ExchangeResponse ExchangeChannel::exchange(ExchangeRequest request) {
  request.run = run_;
  const fs::path req = fs::path(dir_) / request_name(request.step);
  const fs::path resp = fs::path(dir_) / response_name(request.step);
  write_atomic(req.string(), format_request(request));
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::duration_cast<std::chrono::steady_clock::duration>(timeout_);
  while (true) {
    // refuse responses to other steps or runs that land meanwhile
    for (const auto& e : fs::directory_iterator(dir_)) {
      const std::string name = e.path().filename().string();
      if (name.rfind("response.", 0) != 0 || name.size() < 4 || name.substr(name.size() - 4) == ".tmp" ||
          e.path() == resp)
        continue;
      refused_.push_back(fmt::format("{}: out of order (waiting for {})", e.path().string(), resp.filename().string()));
      fs::remove(e.path());
    }
    if (fs::exists(resp)) {
      ExchangeResponse r = parse_response(read_text(resp), resp.string());
      if (r.run != run_) {
        refused_.push_back(fmt::format("{}: stale (run {}, this run is {})", resp.string(), r.run, run_));
        fs::remove(resp);
        continue;
      }
      if (r.step != request.step || r.floes.size() != request.floes.size())
        throw CouplingError(fmt::format("{}: answers step {} with {} floes; the request was step {} with {} floes",
                                        resp.string(), r.step, r.floes.size(), request.step, request.floes.size()));
      for (std::size_t i = 0; i < r.floes.size(); ++i)
        if (r.floes[i].id != request.floes[i].id)
          throw CouplingError(fmt::format("{}: floe {} is {}, the request's is {}", resp.string(), i,
                                          r.floes[i].id, request.floes[i].id));
      fs::remove(req);
      fs::remove(resp);
      return r;
    }
    if (std::chrono::steady_clock::now() > deadline)
      throw CouplingError(fmt::format("exchange timeout at step {}: no {} in {} within {:.0f} s (coupling.timeout)",
                                      request.step, resp.filename().string(), dir_, timeout_.count()));
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
}

void ExchangeChannel::stop() { write_atomic((fs::path(dir_) / "stop").string(), "icedem-exchange 1\nkind stop\nend\n"); }

}  // namespace icedem
