// The DEM side of the file exchange with the OpenFOAM partner (probe mode):
// the record formats, atomic writes, and a channel that sends requests and
// waits for their responses with timeouts. The protocol is coupling/PROTOCOL.md.
#pragma once

#include <chrono>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "dem/core/errors.hpp"

namespace icedem {

constexpr int kExchangeVersion = 1;

/// A file that breaks the protocol (wrong version, corrupt): a coupling failure.
class ProtocolError : public CouplingError {
 public:
  explicit ProtocolError(const std::string& message) : CouplingError(message) {}
};

struct ExchangeHello {
  std::string role;  // "dem" | "partner"
  std::string run;   // run id
  std::string case_hash;
};

struct ExchangeFloe {
  int id;
  Eigen::Vector3d position;  // m, tank frame, centre of mass
  Eigen::Vector3d velocity;  // m/s
  double frontal_area;       // m^2, submerged side area seen by a horizontal flow
  double bottom_area;        // m^2, wetted underside
};

struct ExchangeRequest {
  std::string run;
  long step = 0;
  double time = 0;                     // s
  Eigen::Vector3d structure_position;  // m
  Eigen::Vector3d structure_velocity;  // m/s
  double density = 1000, drag_coefficient = 1, skin_friction_coefficient = 0;
  std::vector<ExchangeFloe> floes;
};

struct ExchangeDrag {
  int id;
  Eigen::Vector3d force;  // N, water on the floe, tank frame
  Eigen::Vector3d water;  // m/s, the sampled water velocity
};

struct ExchangeResponse {
  std::string run;
  long step = 0;
  std::vector<ExchangeDrag> floes;
};

std::string format_hello(const ExchangeHello& h);
std::string format_request(const ExchangeRequest& r);
std::string format_response(const ExchangeResponse& r);

/// Parse a record; `file` names it in errors ("file:line: ..."). Throw ProtocolError.
ExchangeHello parse_hello(const std::string& text, const std::string& file);
ExchangeRequest parse_request(const std::string& text, const std::string& file);
ExchangeResponse parse_response(const std::string& text, const std::string& file);

/// Exchange file names: request.0000000120, response.0000000120.
std::string request_name(long step);
std::string response_name(long step);

/// Writes `<path>.tmp`, then renames it to `path` (readers never see half a file).
void write_atomic(const std::string& path, const std::string& text);

/// The DEM's end of the exchange directory.
class ExchangeChannel {
 public:
  /// Creates the directory if needed, removes every exchange file in it (stale
  /// files of an earlier run), draws a run id and writes dem.hello.
  ExchangeChannel(std::string dir, std::string case_hash, std::chrono::duration<double> timeout);

  /// Waits for the partner's hello of this run; CouplingError after the timeout.
  void wait_for_partner();

  /// Sends the request of `step` and waits for its response (deleting both
  /// then). Stale or out-of-order responses are refused (reported in
  /// `refused()`, then deleted); a corrupt one or the timeout is a CouplingError.
  ExchangeResponse exchange(ExchangeRequest request);

  /// Writes `stop` for the partner.
  void stop();

  const std::string& run() const { return run_; }
  const std::string& dir() const { return dir_; }
  /// Files refused so far, each with the reason.
  const std::vector<std::string>& refused() const { return refused_; }

 private:
  std::string dir_, case_hash_, run_;
  std::chrono::duration<double> timeout_;
  std::vector<std::string> refused_;
};

}  // namespace icedem
