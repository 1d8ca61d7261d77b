#include "coupling/probe_exchange.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <thread>

#include <fmt/format.h>

#include "coupling/foam_case.hpp"
#include "coupling/foam_runner.hpp"
#include "dem/core/constants.hpp"
#include "dem/core/errors.hpp"
#include "dem/layout/polygon.hpp"
#include "dem/step/state.hpp"

extern char** environ;

namespace fs = std::filesystem;

namespace icedem {
namespace {

// coupling.exchange_dir, or a fresh temporary directory (removed after a run that succeeds)
std::string exchange_dir(const Scene& scene) {
  if (!scene.coupling.exchange_dir.empty()) return scene.coupling.exchange_dir;
  std::string tmpl = (fs::temp_directory_path() / "icedem-exchange-XXXXXX").string();
  if (!::mkdtemp(tmpl.data())) throw CouplingError("cannot create a temporary exchange directory");
  return tmpl;
}

// the partner as a child process, its output to DIR/partner.log
pid_t spawn_partner(const std::string& dir, const std::string& case_dir) {
  const std::string script = (fs::path(ICEDEM_COUPLING_DIR) / "foam_partner.py").string();
  const std::string log = (fs::path(dir) / "partner.log").string();
  std::vector<std::string> args{"/usr/bin/python3", script, "--exchange", dir, "--case", case_dir};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  pid_t pid = -1;
  const int rc = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) throw CouplingError(fmt::format("cannot start the OpenFOAM partner {} ({})", script, std::strerror(rc)));
  return pid;
}

}  // namespace

ProbeDragExchange::ProbeDragExchange(const Scene& scene) {
  solved_flow_grid(scene, std::cerr);  // the partner samples the solved case
  const FoamCaseSpec spec = foam_case_spec(scene);
  const std::string case_dir = foam_case_dir(spec, scene.coupling.cache_dir);
  const std::string dir = exchange_dir(scene);
  if (scene.coupling.exchange_dir.empty()) temporary_dir_ = dir;
  channel_ = std::make_unique<ExchangeChannel>(dir, foam_case_hash(spec),
                                               std::chrono::duration<double>(scene.coupling.timeout));
  if (scene.coupling.spawn_partner) partner_ = spawn_partner(dir, case_dir);
  std::cerr << fmt::format("coupled flow (probe mode): exchanging through {} every {} steps{}\n", dir,
                           scene.coupling.exchange_steps,
                           partner_ > 0 ? fmt::format(" with partner pid {}", partner_) : " with an external partner");
  try {
    channel_->wait_for_partner();
  } catch (...) {
    finish(false);
    throw;
  }
}

ProbeDragExchange::~ProbeDragExchange() { finish(false); }

void ProbeDragExchange::update(const Scene& scene, const State& state) {
  if (state.step % scene.coupling.exchange_steps != 0) return;
  ExchangeRequest r;
  r.step = state.step;
  r.time = state.time;
  r.structure_position = state.structure_position;
  r.structure_velocity = state.structure_velocity;
  r.density = scene.water.density;
  r.drag_coefficient = scene.water.drag_coefficient;
  r.skin_friction_coefficient = scene.water.skin_friction_coefficient;
  const std::vector<FloeBody>& floes = state.world->floes();
  const double draft = scene.ice.draft;
  for (std::size_t i = 0; i < floes.size(); ++i) {
    const btRigidBody& b = *floes[i].body;
    if (liveness(b) != Liveness::kAwake) continue;  // sleeping floes are at rest: no drag
    const Polygon& outline = floes[i].shape->outline;
    double perimeter = 0;
    for (std::size_t k = 0; k < outline.size(); ++k) perimeter += (outline[(k + 1) % outline.size()] - outline[k]).norm();
    // the mean width of a convex outline seen from a random direction is perimeter / pi (Cauchy)
    r.floes.push_back({static_cast<int>(i), to_eigen(b.getCenterOfMassPosition()), to_eigen(b.getLinearVelocity()),
                       draft * perimeter / kPi, area(outline)});
  }
  const ExchangeResponse response = channel_->exchange(r);
  drag_.assign(floes.size(), Eigen::Vector3d::Zero());
  for (const ExchangeDrag& d : response.floes) drag_[d.id] = d.force;
  ++exchanges_;
}

Eigen::Vector3d ProbeDragExchange::drag(int body) const {
  return body >= 0 && static_cast<std::size_t>(body) < drag_.size() ? drag_[body] : Eigen::Vector3d::Zero();
}

void ProbeDragExchange::finish(bool succeeded) noexcept {
  if (finished_) return;
  finished_ = true;
  try {
    if (channel_) channel_->stop();
  } catch (...) {
  }
  if (partner_ > 0) {
    // give the partner a second to see `stop`, then make sure it is gone
    bool gone = false;
    for (int i = 0; i < 100 && !gone; ++i) {
      gone = ::waitpid(partner_, nullptr, WNOHANG) == partner_;
      if (!gone) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    if (!gone) {
      ::kill(partner_, SIGTERM);
      ::waitpid(partner_, nullptr, 0);
    }
  }
  // a temporary directory of a run that succeeded holds nothing worth keeping (a
  // sweep would fill /tmp); after a failure its partner.log says what happened
  if (succeeded && !temporary_dir_.empty()) {
    std::error_code ec;
    fs::remove_all(temporary_dir_, ec);
  }
}

std::unique_ptr<DragExchange> make_drag_exchange(const Scene& scene) {
  if (scene.flow.model != FlowModel::kCoupled || scene.coupling.mode != CouplingMode::kProbe) return nullptr;
  return std::make_unique<ProbeDragExchange>(scene);
}

}  // namespace icedem
