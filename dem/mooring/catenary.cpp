#include "dem/mooring/catenary.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace icedem {
namespace {

// XF, ZF for (HF, VF) and their Jacobian d(XF, ZF) / d(HF, VF): the closed form of catenary.hpp
struct Shape {
  Eigen::Vector2d xz;
  Eigen::Matrix2d jacobian;
  double laid = 0;  // m
};

Shape shape(const CatenaryLine& line, double h, double v) {
  const double w = line.weight, L = line.length, ea = line.axial_stiffness, cb = line.seabed_friction;
  const double r = v / h, s = std::sqrt(1 + r * r);
  Shape out;
  if (v < w * L) {  // part of the line on the seabed
    const double laid = L - v / w;
    double friction = 0, dfriction_dh = 0, dfriction_dv = 0;  // -(CB w / 2EA)(L_B^2 - x_B^2) and its derivatives
    if (cb > 0) {
      const double xb = laid - h / (cb * w);
      if (xb > 0) {  // the tension reaches zero on the seabed, x_B from the anchor
        friction = -laid * h / ea + h * h / (2 * ea * cb * w);
        dfriction_dh = -laid / ea + h / (ea * cb * w);
        dfriction_dv = h / (w * ea);
      } else {
        friction = -cb * w / (2 * ea) * laid * laid;
        dfriction_dv = cb * laid / ea;
      }
    }
    out.laid = laid;
    out.xz = {laid + h / w * std::asinh(r) + h * L / ea + friction, h / w * (s - 1) + v * v / (2 * ea * w)};
    out.jacobian << (std::asinh(r) - r / s) / w + L / ea + dfriction_dh, -1 / w + 1 / (w * s) + dfriction_dv,
        (1 / s - 1) / w, r / (w * s) + v / (ea * w);
  } else {  // hanging whole
    const double ra = (v - w * L) / h, sa = std::sqrt(1 + ra * ra);
    out.xz = {h / w * (std::asinh(r) - std::asinh(ra)) + h * L / ea, h / w * (s - sa) + (v * L - w * L * L / 2) / ea};
    out.jacobian << (std::asinh(r) - std::asinh(ra) - r / s + ra / sa) / w + L / ea, (1 / s - 1 / sa) / w,
        (1 / s - 1 / sa) / w, (r / s - ra / sa) / w + L / ea;
  }
  return out;
}

}  // namespace

CatenaryState solve_catenary(const CatenaryLine& line, double xf, double zf) {
  const double w = line.weight, L = line.length, ea = line.axial_stiffness, cb = line.seabed_friction;
  for (const auto& [name, value] : {std::pair<const char*, double>{"length", L}, {"weight", w}, {"axial stiffness", ea}})
    if (!(value > 0) || !std::isfinite(value))
      throw std::invalid_argument(fmt::format("a mooring line's {} must be positive and finite, not {}", name, value));
  if (!(cb >= 0)) throw std::invalid_argument(fmt::format("a mooring line's seabed friction must be >= 0, not {}", cb));
  if (!(zf > 0) || !(xf >= 0))
    throw std::invalid_argument(fmt::format("a fairlead {} m above and {} m from its anchor: it must be above it", zf, xf));
  CatenaryState out;
  // so slack that the line hangs straight down from the fairlead and lies on the seabed from there:
  // HF = 0, the hanging part stretched by its own weight (w l^2 / (2 EA) over its length l)
  // l + w l^2 / (2 EA) = ZF for the unstretched hanging length l, written without the cancellation of
  // sqrt(2 ZF EA / w + (EA / w)^2) - EA / w
  const double hanging = 2 * zf / (1 + std::sqrt(1 + 2 * zf * w / ea));
  if (hanging < L && xf <= L - hanging) {
    out.vertical = w * hanging;
    out.laid_length = L - hanging;
    out.stiffness << 0, 0, 0, w / (1 + w * hanging / ea);  // dVF/dZF of the hanging part (its weight per height)
    return out;
  }
  // first guess (Peyrot and Goulois 1979, as FAST's catenary routine)
  const double slack = (L * L - zf * zf) / (xf * xf) - 1;
  const double lambda = xf == 0 ? 1e6 : slack > 0 ? std::sqrt(3 * slack) : 0.2;
  double h = std::max(std::abs(0.5 * w * xf / lambda), 1e-6 * w * L), v = 0.5 * w * (zf / std::tanh(lambda) + L);
  const Eigen::Vector2d target(xf, zf);
  const double tolerance = 1e-12 * std::max(1.0, std::hypot(xf, zf));
  for (int k = 1; k <= 200; ++k) {
    const Shape sh = shape(line, h, v);
    const Eigen::Vector2d residual = sh.xz - target;
    if (residual.norm() < tolerance) {
      out.horizontal = h;
      out.vertical = v;
      out.laid_length = v < w * L ? sh.laid : 0;
      out.anchor_horizontal = v < w * L ? std::max(h - cb * w * out.laid_length, 0.0) : h;
      out.anchor_vertical = v < w * L ? 0 : v - w * L;
      out.iterations = k - 1;
      out.stiffness = sh.jacobian.inverse();
      return out;
    }
    Eigen::Vector2d step = sh.jacobian.partialPivLu().solve(-residual);
    // keep HF positive: a step that would cross zero goes halfway to it instead
    if (h + step.x() <= 0) step *= 0.5 * h / -step.x();
    h += step.x();
    v += step.y();
  }
  throw std::runtime_error(fmt::format("a mooring line (L {} m, w {} N/m, EA {} N) found no shape for its fairlead "
                                       "{} m from and {} m above its anchor in 200 Newton steps",
                                       L, w, ea, xf, zf));
}

std::vector<Eigen::Vector2d> catenary_profile(const CatenaryLine& line, const CatenaryState& state, double xf,
                                              int points) {
  if (points < 2) throw std::invalid_argument(fmt::format("a line's profile needs 2 points or more, not {}", points));
  const double w = line.weight, L = line.length, ea = line.axial_stiffness, cb = line.seabed_friction;
  const double h = state.horizontal, laid = state.laid_length;
  std::vector<double> at;  // unstretched length from the anchor
  for (int i = 0; i < points; ++i) at.push_back(L * i / (points - 1));
  if (laid > 0 && laid < L) {  // the touchdown point among them, in place of the nearest
    auto nearest = std::min_element(at.begin() + 1, at.end() - 1,
                                    [&](double a, double b) { return std::abs(a - laid) < std::abs(b - laid); });
    if (points > 2) *nearest = laid;
  }
  std::vector<Eigen::Vector2d> out;
  if (h <= 0) {  // hanging straight down from the fairlead onto a slack laid part
    for (double s : at) {
      if (s <= laid) out.emplace_back(laid > 0 ? xf * s / laid : xf, 0.0);
      else out.emplace_back(xf, (s - laid) + w * (s - laid) * (s - laid) / (2 * ea));  // tension w u, u above the seabed
    }
    return out;
  }
  // the laid part's stretch: the integral of its tension from the anchor, T = max(HF - CB w (L_B - s), 0)
  const double xb = cb > 0 ? std::max(laid - h / (cb * w), 0.0) : 0.0;
  auto laid_stretch = [&](double s) {
    if (cb <= 0) return h * s / ea;
    if (s <= xb) return 0.0;
    return ((h - cb * w * laid) * (s - xb) + cb * w * (s * s - xb * xb) / 2) / ea;
  };
  const double va = laid > 0 ? 0.0 : state.vertical - w * L;  // vertical tension where the hanging part starts
  const double s0 = laid > 0 ? laid : 0.0;                    // and its unstretched length from the anchor
  const double x0 = laid > 0 ? laid + laid_stretch(laid) : 0.0;
  for (double s : at) {
    if (laid > 0 && s <= laid) {
      out.emplace_back(s + laid_stretch(s), 0.0);
      continue;
    }
    const double u = s - s0, v = va + w * u;  // along the hanging part; the vertical tension there
    out.emplace_back(x0 + h / w * (std::asinh(v / h) - std::asinh(va / h)) + h * u / ea,
                     h / w * (std::sqrt(1 + (v / h) * (v / h)) - std::sqrt(1 + (va / h) * (va / h))) +
                         (va * u + w * u * u / 2) / ea);
  }
  return out;
}

}  // namespace icedem
