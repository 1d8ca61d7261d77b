#include "dem/contact_method.hpp"

#include <stdexcept>

#include "dem/contact_apgd.hpp"
#include "dem/contact_newton.hpp"
#include "dem/contact_pgs.hpp"
#include "dem/contact_siconos.hpp"

namespace icedem {
std::vector<std::string> contact_method_names() {
  return {"pgs", "pgs_cone", "newton", "apgd", "siconos_nsgs", "siconos_nsn_ac", "siconos_nsn_fb", "siconos_prox", "siconos_admm"};
}

std::unique_ptr<ContactMethod> make_contact_method(const std::string& name) {
  if (name == "pgs") return std::make_unique<ProjectedGaussSeidel>(false);
  if (name == "pgs_cone") return std::make_unique<ProjectedGaussSeidel>(true);
  if (name == "newton") return std::make_unique<PrimalNewton>();
  if (name == "apgd") return std::make_unique<AcceleratedProjectedGradient>();
  if (name == "siconos_nsgs") return std::make_unique<SiconosMethod>(SiconosMethod::kNsgs);
  if (name == "siconos_nsn_ac") return std::make_unique<SiconosMethod>(SiconosMethod::kNsnAc);
  if (name == "siconos_nsn_fb") return std::make_unique<SiconosMethod>(SiconosMethod::kNsnFb);
  if (name == "siconos_prox") return std::make_unique<SiconosMethod>(SiconosMethod::kProx);
  if (name == "siconos_admm") return std::make_unique<SiconosMethod>(SiconosMethod::kAdmm);
  throw std::invalid_argument("unknown contact method \"" + name + "\"");
}

}  // namespace icedem
