#include "dem/contact_method.hpp"

#include <stdexcept>

#include "dem/contact_newton.hpp"
#include "dem/contact_pgs.hpp"
#include "dem/contact_siconos.hpp"

namespace icedem {
namespace {

// Siconos numerics' solver ids (siconos/numerics/Friction_cst.h)
constexpr int kSiconosNsgs = 500, kSiconosProx = 502, kSiconosNsnAc = 504, kSiconosNsnFb = 513, kSiconosAdmm = 523;

}  // namespace

std::vector<std::string> contact_method_names() {
  return {"pgs", "pgs_cone", "newton", "siconos_nsgs", "siconos_nsn_ac", "siconos_nsn_fb", "siconos_prox", "siconos_admm"};
}

std::unique_ptr<ContactMethod> make_contact_method(const std::string& name) {
  if (name == "pgs") return std::make_unique<ProjectedGaussSeidel>(false);
  if (name == "pgs_cone") return std::make_unique<ProjectedGaussSeidel>(true);
  if (name == "newton") return std::make_unique<PrimalNewton>();
  if (name == "siconos_nsgs") return std::make_unique<SiconosMethod>(kSiconosNsgs);
  if (name == "siconos_nsn_ac") return std::make_unique<SiconosMethod>(kSiconosNsnAc);
  if (name == "siconos_nsn_fb") return std::make_unique<SiconosMethod>(kSiconosNsnFb);
  if (name == "siconos_prox") return std::make_unique<SiconosMethod>(kSiconosProx);
  if (name == "siconos_admm") return std::make_unique<SiconosMethod>(kSiconosAdmm);
  throw std::invalid_argument("unknown contact method \"" + name + "\"");
}

}  // namespace icedem
