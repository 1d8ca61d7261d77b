// The file exchange of probe mode (coupling/PROTOCOL.md) against a fake
// partner thread (no OpenFOAM): records round-trip, bad files are refused with
// messages naming file and line, and the channel rejects stale, out-of-order
// and half-written files and times out with a clear error.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <cmath>
#include <cstdlib>
#include <thread>

#include "coupling/exchange_protocol.hpp"

using namespace icedem;
namespace fs = std::filesystem;

namespace {

ExchangeRequest sample_request() {
  ExchangeRequest r;
  r.run = "abc-1";
  r.step = 120;
  r.time = 2.4;
  r.structure_position = {6.1, 0.0, 0.0};
  r.structure_velocity = {0.07, 0.0, 0.0};
  r.density = 1000;
  r.drag_coefficient = 1.0;
  r.skin_friction_coefficient = 0.0092;
  r.floes = {{3, {7.0, -0.015, 0.2}, {0.01, 0.0, -0.002}, 0.0029, 0.09},
             {8, {7.4, -0.015, -0.3}, {0.0, 0.0, 0.0}, 0.0029, 0.09}};
  return r;
}

std::string dir_for(const std::string& name) {
  const fs::path d = fs::path(ICEDEM_TEST_TMP) / name;
  fs::remove_all(d);
  return d.string();
}

std::string read(const fs::path& p) {
  std::ifstream in(p);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const CouplingError& e) {
    return e.what();
  }
  return "";
}

// waits for a file to appear (the fake partner's side of the polling)
bool appears(const fs::path& p, double seconds = 5) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (!fs::exists(p))
    if (std::chrono::steady_clock::now() > end) return false;
    else std::this_thread::sleep_for(std::chrono::milliseconds(1));
  return true;
}

// a partner: hello for the DEM's run, then one response per request with a drag of
// 1 N per floe along -x, written through `write` (to inject faults before it)
void partner(const std::string& dir, const std::function<void(const ExchangeResponse&)>& before = {}) {
  const fs::path hello = fs::path(dir) / "dem.hello";
  ASSERT_TRUE(appears(hello));
  const ExchangeHello h = parse_hello(read(hello), hello.string());
  write_atomic((fs::path(dir) / "partner.hello").string(), format_hello({"partner", h.run, h.case_hash}));
  const fs::path req = fs::path(dir) / request_name(120);
  ASSERT_TRUE(appears(req));
  const ExchangeRequest q = parse_request(read(req), req.string());
  ExchangeResponse r{q.run, q.step, {}};
  for (const ExchangeFloe& f : q.floes) r.floes.push_back({f.id, {-1.0, 0.0, 0.0}, {-0.07, 0.0, 0.0}});
  if (before) before(r);
  write_atomic((fs::path(dir) / response_name(q.step)).string(), format_response(r));
}

}  // namespace

TEST(ExchangeProtocol, RecordsRoundTripExactly) {
  const ExchangeRequest r = sample_request();
  const ExchangeRequest back = parse_request(format_request(r), "request");
  EXPECT_EQ(back.run, r.run);
  EXPECT_EQ(back.step, r.step);
  EXPECT_EQ(back.time, r.time);  // 17 significant digits: bit-exact doubles
  EXPECT_EQ(back.structure_velocity, r.structure_velocity);
  EXPECT_EQ(back.skin_friction_coefficient, r.skin_friction_coefficient);
  ASSERT_EQ(back.floes.size(), 2u);
  EXPECT_EQ(back.floes[1].id, 8);
  EXPECT_EQ(back.floes[0].position, r.floes[0].position);
  EXPECT_EQ(back.floes[0].velocity, r.floes[0].velocity);
  EXPECT_EQ(back.floes[0].frontal_area, r.floes[0].frontal_area);
  const ExchangeResponse p{"abc-1", 120, {{3, {-0.1, 0.0, 0.02}, {-0.08, 0.0, 0.01}}}};
  const ExchangeResponse pb = parse_response(format_response(p), "response");
  EXPECT_EQ(pb.floes[0].force, p.floes[0].force);
  EXPECT_EQ(pb.floes[0].water, p.floes[0].water);
}

TEST(ExchangeProtocol, BadFilesAreRefusedNamingFileAndLine) {
  std::string text = format_request(sample_request());
  std::string v2 = text;
  v2.replace(0, 17, "icedem-exchange 2");
  std::string msg = error_of([&] { parse_request(v2, "d/request.0000000120"); });
  EXPECT_NE(msg.find("d/request.0000000120:1"), std::string::npos) << msg;
  EXPECT_NE(msg.find("version"), std::string::npos) << msg;
  // half a file (a writer that did not use write_atomic): no final "end"
  msg = error_of([&] { parse_request(text.substr(0, text.size() / 2), "r"); });
  EXPECT_NE(msg.find("half-written"), std::string::npos) << msg;
  // the first floe line (line 9) with its last number cut off
  std::string bad = text;
  const std::size_t line9 = bad.find("\n3 ") + 1, eol = bad.find('\n', line9);
  bad.erase(bad.rfind(' ', eol), eol - bad.rfind(' ', eol));
  msg = error_of([&] { parse_request(bad, "r"); });
  EXPECT_NE(msg.find("r:9: expected 9 numbers"), std::string::npos) << msg;
  msg = error_of([&] { parse_response(text, "r"); });  // a request is not a response
  EXPECT_NE(msg.find("kind 'request', expected 'response'"), std::string::npos) << msg;
}

TEST(ExchangeProtocol, ChannelExchangesWithAPartnerAndCleansStaleFiles) {
  const std::string dir = dir_for("exchange_ok");
  fs::create_directories(dir);
  // an earlier run's leftovers: removed when the channel opens
  write_atomic(dir + "/" + response_name(120), format_response({"old-run", 120, {}}));
  write_atomic(dir + "/partner.hello", format_hello({"partner", "old-run", "x"}));
  ExchangeChannel channel(dir, "hash1", std::chrono::seconds(5));
  EXPECT_FALSE(fs::exists(dir + "/" + response_name(120)));
  std::thread p([&] { partner(dir); });
  channel.wait_for_partner();
  const ExchangeResponse r = channel.exchange(sample_request());
  p.join();
  ASSERT_EQ(r.floes.size(), 2u);
  EXPECT_EQ(r.floes[1].id, 8);
  EXPECT_EQ(r.floes[0].force, Eigen::Vector3d(-1.0, 0.0, 0.0));
  EXPECT_FALSE(fs::exists(dir + "/" + request_name(120)));  // both files consumed
  EXPECT_FALSE(fs::exists(dir + "/" + response_name(120)));
  EXPECT_TRUE(channel.refused().empty());
}

TEST(ExchangeProtocol, StaleAndOutOfOrderResponsesAreRefused) {
  const std::string dir = dir_for("exchange_refuse");
  ExchangeChannel channel(dir, "hash1", std::chrono::seconds(5));
  std::thread p([&] {
    partner(dir, [&](const ExchangeResponse& good) {
      // before the right answer: one for another step and one of another run
      ExchangeResponse other = good;
      other.step = 119;
      write_atomic(dir + "/" + response_name(119), format_response(other));
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      ExchangeResponse stale = good;
      stale.run = "old-run";
      write_atomic(dir + "/" + response_name(120), format_response(stale));
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      while (fs::exists(dir + "/" + response_name(120))) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    });
  });
  channel.wait_for_partner();
  const ExchangeResponse r = channel.exchange(sample_request());
  p.join();
  EXPECT_EQ(r.run, channel.run());
  ASSERT_EQ(channel.refused().size(), 2u);
  EXPECT_NE(channel.refused()[0].find("out of order"), std::string::npos) << channel.refused()[0];
  EXPECT_NE(channel.refused()[1].find("stale"), std::string::npos) << channel.refused()[1];
}

TEST(ExchangeProtocol, MissingPartnerAndLateResponseTimeOutWithClearErrors) {
  const std::string dir = dir_for("exchange_timeout");
  ExchangeChannel channel(dir, "hash1", std::chrono::milliseconds(200));
  std::string msg = error_of([&] { channel.wait_for_partner(); });
  EXPECT_NE(msg.find("no OpenFOAM partner"), std::string::npos) << msg;
  EXPECT_NE(msg.find("coupling.timeout"), std::string::npos) << msg;
  msg = error_of([&] { channel.exchange(sample_request()); });
  EXPECT_NE(msg.find("exchange timeout at step 120"), std::string::npos) << msg;
  EXPECT_NE(msg.find(dir), std::string::npos) << msg;
}

TEST(ExchangeProtocol, CorruptResponseIsAnError) {
  const std::string dir = dir_for("exchange_corrupt");
  ExchangeChannel channel(dir, "hash1", std::chrono::seconds(5));
  std::thread p([&] {
    partner(dir, [&](const ExchangeResponse&) {
      // renamed into place without its end: a partner that breaks the atomic-write rule
      std::ofstream(dir + "/" + response_name(120)) << "icedem-exchange 1\nkind response\nrun x\n";
      while (fs::exists(dir + "/" + response_name(120))) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    });
  });
  channel.wait_for_partner();
  const std::string msg = error_of([&] { channel.exchange(sample_request()); });
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  fs::remove(dir + "/" + response_name(120));  // let the partner thread finish
  p.join();
  EXPECT_NE(msg.find("half-written"), std::string::npos) << msg;
}

namespace {

// the real partner script, without OpenFOAM (--still-water), as a separate process
void start_partner(const std::string& dir) {
  const std::string cmd = "/usr/bin/python3 " + std::string(ICEDEM_SOURCE_DIR) +
                          "/coupling/foam_partner.py --exchange " + dir +
                          " --still-water --case-hash hash1 --idle-timeout 20 > " + dir + ".partner.log 2>&1 &";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
}

}  // namespace

TEST(ExchangeProtocol, PartnerProcessAnswersWithTheDragLaw) {
  const std::string dir = dir_for("exchange_python");
  ExchangeChannel channel(dir, "hash1", std::chrono::seconds(20));
  start_partner(dir);
  channel.wait_for_partner();
  const ExchangeRequest request = sample_request();
  const ExchangeResponse r = channel.exchange(request);
  channel.stop();
  ASSERT_EQ(r.floes.size(), 2u);
  // still water: F = -1/2 rho (C_d frontal + C_f bottom) |v_h| v_h
  const ExchangeFloe& f = request.floes[0];
  const double k = 0.5 * 1000 * (1.0 * f.frontal_area + 0.0092 * f.bottom_area) * std::hypot(0.01, -0.002);
  EXPECT_NEAR(r.floes[0].force.x(), -k * 0.01, 1e-15);
  EXPECT_NEAR(r.floes[0].force.z(), -k * -0.002, 1e-15);
  EXPECT_EQ(r.floes[0].force.y(), 0.0);
  EXPECT_EQ(r.floes[1].force, Eigen::Vector3d::Zero());  // at rest: no drag
}

TEST(ExchangeProtocol, RestartedPartnerAnswersThePendingRequest) {
  const std::string dir = dir_for("exchange_restart");
  ExchangeChannel channel(dir, "hash1", std::chrono::seconds(20));
  // the partner "crashed" before the request: the request waits in the directory
  // until a new partner starts, picks up the run from dem.hello and answers it
  write_atomic(dir + "/partner.hello", format_hello({"partner", channel.run(), "hash1"}));
  channel.wait_for_partner();
  std::thread later([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    start_partner(dir);
  });
  const ExchangeResponse r = channel.exchange(sample_request());
  later.join();
  channel.stop();
  EXPECT_EQ(r.step, 120);
  EXPECT_EQ(r.floes.size(), 2u);
}
