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

}  // namespace icedem
