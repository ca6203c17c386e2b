#include "parksim/scenario/maps/SvgPath.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <string>

namespace parksim {

namespace {

constexpr double kSvgPi = 3.14159265358979323846;
// Chords per curve at most: a tolerance far below a curve's size cannot make one curve explode.
constexpr int kMaxChordsPerCurve = 4096;

bool isSvgSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; }

// A cursor over an attribute's text with SVG's number and separator rules.
class SvgScanner {
 public:
  explicit SvgScanner(std::string_view text) : text_(text) {}

  bool atEnd() {
    skipSpace();
    return pos_ >= text_.size();
  }
  char peek() {
    skipSpace();
    return pos_ < text_.size() ? text_[pos_] : '\0';
  }
  void advance() { ++pos_; }
  std::size_t position() const { return pos_; }

  // Whitespace, then at most one comma and more whitespace.
  void skipSeparator() {
    skipSpace();
    if (pos_ < text_.size() && text_[pos_] == ',') {
      ++pos_;
      skipSpace();
    }
  }

  bool startsNumber() {
    skipSpace();
    if (pos_ >= text_.size()) return false;
    const char c = text_[pos_];
    return (c >= '0' && c <= '9') || c == '.' || c == '-' || c == '+';
  }

  double number(const char* what) {
    skipSpace();
    const std::size_t start = pos_;
    std::size_t i = pos_;
    if (i < text_.size() && (text_[i] == '+' || text_[i] == '-')) ++i;
    const std::size_t mantissa = i;
    while (i < text_.size() && std::isdigit(static_cast<unsigned char>(text_[i]))) ++i;
    if (i < text_.size() && text_[i] == '.') {
      ++i;
      while (i < text_.size() && std::isdigit(static_cast<unsigned char>(text_[i]))) ++i;
    }
    if (i == mantissa || (i == mantissa + 1 && text_[mantissa] == '.')) {
      fail(std::string("expected a number (") + what + ")");
    }
    if (i < text_.size() && (text_[i] == 'e' || text_[i] == 'E')) {
      std::size_t k = i + 1;
      if (k < text_.size() && (text_[k] == '+' || text_[k] == '-')) ++k;
      if (k < text_.size() && std::isdigit(static_cast<unsigned char>(text_[k]))) {
        while (k < text_.size() && std::isdigit(static_cast<unsigned char>(text_[k]))) ++k;
        i = k;
      }
    }
    const std::size_t from = text_[start] == '+' ? start + 1 : start;
    double v = 0.0;
    const auto [end, ec] = std::from_chars(text_.data() + from, text_.data() + i, v);
    if (ec != std::errc() || end != text_.data() + i || !std::isfinite(v)) {
      fail("number '" + std::string(text_.substr(start, i - start)) + "' is out of range");
    }
    pos_ = i;
    skipSeparator();
    return v;
  }

  // An arc flag: a single 0 or 1, which may stand right before the next number.
  bool flag() {
    skipSpace();
    if (pos_ >= text_.size() || (text_[pos_] != '0' && text_[pos_] != '1')) {
      fail("expected an arc flag 0 or 1");
    }
    const bool v = text_[pos_] == '1';
    ++pos_;
    skipSeparator();
    return v;
  }

  [[noreturn]] void fail(const std::string& what) const {
    const std::size_t at = std::min(pos_, text_.size());
    const std::size_t from = at > 12 ? at - 12 : 0;
    throw SvgSyntaxError(what + " at character " + std::to_string(at + 1) + " (near \"" +
                         std::string(text_.substr(from, 24)) + "\")");
  }

  void skipSpace() {
    while (pos_ < text_.size() && isSvgSpace(text_[pos_])) ++pos_;
  }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
};

// Appends points of a flattened curve; counts against the budget of the whole path.
class RingBuilder {
 public:
  explicit RingBuilder(std::size_t max_vertices) : max_(max_vertices) {}

  void start(const Eigen::Vector2d& p) {
    finish();
    current_.push_back(p);
  }
  void add(const Eigen::Vector2d& p) {
    if (++count_ > max_) {
      throw SvgSyntaxError("the path flattens into more than " + std::to_string(max_) +
                           " vertices (docs/limits.md)");
    }
    if (current_.empty() || current_.back() != p) current_.push_back(p);
  }
  void finish() {
    if (current_.size() > 1 && current_.back() == current_.front()) current_.pop_back();
    if (!current_.empty()) rings_.push_back(std::move(current_));
    current_.clear();
  }
  std::vector<std::vector<Eigen::Vector2d>> take() {
    finish();
    return std::move(rings_);
  }

 private:
  std::size_t max_;
  std::size_t count_ = 0;
  std::vector<Eigen::Vector2d> current_;
  std::vector<std::vector<Eigen::Vector2d>> rings_;
};

int chordsFor(double bound) {
  if (!(bound > 0.0)) return 1;
  return static_cast<int>(std::clamp(std::ceil(bound), 1.0, double(kMaxChordsPerCurve)));
}

void cubic(RingBuilder& out, const Eigen::Vector2d& p0, const Eigen::Vector2d& p1,
           const Eigen::Vector2d& p2, const Eigen::Vector2d& p3, double tol) {
  // Uniform steps stray at most |B''|max / (8 n^2) from the curve, |B''| <= 6 max |second
  // differences of the control points|.
  const double m = std::max((p0 - 2 * p1 + p2).norm(), (p1 - 2 * p2 + p3).norm());
  const int n = chordsFor(std::sqrt(0.75 * m / tol));
  for (int i = 1; i <= n; ++i) {
    const double t = double(i) / n;
    const double u = 1.0 - t;
    out.add(u * u * u * p0 + 3 * u * u * t * p1 + 3 * u * t * t * p2 + t * t * t * p3);
  }
}

void quadratic(RingBuilder& out, const Eigen::Vector2d& p0, const Eigen::Vector2d& p1,
               const Eigen::Vector2d& p2, double tol) {
  const double m = (p0 - 2 * p1 + p2).norm();
  const int n = chordsFor(std::sqrt(0.25 * m / tol));
  for (int i = 1; i <= n; ++i) {
    const double t = double(i) / n;
    const double u = 1.0 - t;
    out.add(u * u * p0 + 2 * u * t * p1 + t * t * p2);
  }
}

int arcChords(double radius, double sweep, double tol) {
  // A chord over angle s strays r (1 - cos(s / 2)) from the arc.
  if (!(radius > tol)) return chordsFor(std::abs(sweep) / (kSvgPi / 2));
  const double step = 2.0 * std::acos(1.0 - tol / radius);
  return chordsFor(std::abs(sweep) / step);
}

// SVG's endpoint arc (implementation notes F.6.5), flattened after p0 up to p1.
void arc(RingBuilder& out, const Eigen::Vector2d& p0, double rx, double ry, double phi_deg,
         bool large, bool sweep, const Eigen::Vector2d& p1, double tol) {
  if (p0 == p1) return;
  rx = std::abs(rx);
  ry = std::abs(ry);
  if (rx == 0.0 || ry == 0.0) {
    out.add(p1);
    return;
  }
  const double phi = phi_deg * kSvgPi / 180.0;
  const double cp = std::cos(phi);
  const double sp = std::sin(phi);
  const Eigen::Vector2d h = 0.5 * (p0 - p1);
  const double x1 = cp * h.x() + sp * h.y();
  const double y1 = -sp * h.x() + cp * h.y();
  const double lambda = (x1 * x1) / (rx * rx) + (y1 * y1) / (ry * ry);
  if (lambda > 1.0) {
    rx *= std::sqrt(lambda);
    ry *= std::sqrt(lambda);
  }
  const double num = rx * rx * ry * ry - rx * rx * y1 * y1 - ry * ry * x1 * x1;
  const double den = rx * rx * y1 * y1 + ry * ry * x1 * x1;
  double k = std::sqrt(std::max(0.0, num / den));
  if (large == sweep) k = -k;
  const double cx1 = k * rx * y1 / ry;
  const double cy1 = -k * ry * x1 / rx;
  const Eigen::Vector2d mid = 0.5 * (p0 + p1);
  const Eigen::Vector2d c(cp * cx1 - sp * cy1 + mid.x(), sp * cx1 + cp * cy1 + mid.y());
  const auto angle = [](double ux, double uy, double vx, double vy) {
    return std::atan2(ux * vy - uy * vx, ux * vx + uy * vy);
  };
  const double t1 = angle(1.0, 0.0, (x1 - cx1) / rx, (y1 - cy1) / ry);
  double dt = angle((x1 - cx1) / rx, (y1 - cy1) / ry, (-x1 - cx1) / rx, (-y1 - cy1) / ry);
  if (!sweep && dt > 0) dt -= 2 * kSvgPi;
  if (sweep && dt < 0) dt += 2 * kSvgPi;
  const int n = arcChords(std::max(rx, ry), dt, tol);
  for (int i = 1; i < n; ++i) {
    const double t = t1 + dt * i / n;
    const double ex = rx * std::cos(t);
    const double ey = ry * std::sin(t);
    out.add({cp * ex - sp * ey + c.x(), sp * ex + cp * ey + c.y()});
  }
  out.add(p1);  // exactly the end point the path names
}

}  // namespace

SvgTransform SvgTransform::after(const SvgTransform& m) const {
  return {a * m.a + c * m.b, b * m.a + d * m.b,     a * m.c + c * m.d,
          b * m.c + d * m.d, a * m.e + c * m.f + e, b * m.e + d * m.f + f};
}

double SvgTransform::maxStretch() const {
  // Largest singular value of [a c; b d].
  const double s = a * a + b * b + c * c + d * d;
  const double det = a * d - b * c;
  return std::sqrt(0.5 * (s + std::sqrt(std::max(0.0, s * s - 4.0 * det * det))));
}

bool SvgTransform::isSimilarity() const {
  const double n0 = std::hypot(a, b);
  const double n1 = std::hypot(c, d);
  const double tol = 1e-12 * std::max(n0, n1);
  return n0 > 0.0 && std::abs(n0 - n1) <= tol && std::abs(a * c + b * d) <= tol * std::max(n0, n1);
}

double SvgTransform::scale() const { return std::hypot(a, b); }

SvgTransform parseSvgTransform(std::string_view text) {
  SvgScanner s(text);
  SvgTransform total;
  while (!s.atEnd()) {
    std::string name;
    while (!s.atEnd() && std::isalpha(static_cast<unsigned char>(s.peek()))) {
      name += s.peek();
      s.advance();
    }
    if (name != "matrix" && name != "translate" && name != "scale" && name != "rotate" &&
        name != "skewX" && name != "skewY") {
      if (name.empty()) {
        s.fail("expected a transform (matrix, translate, scale, rotate, skewX, skewY)");
      }
      throw SvgSyntaxError("unknown transform '" + name + "' at character " +
                           std::to_string(s.position() - name.size() + 1) + " (near \"" +
                           std::string(text.substr(s.position() - name.size(), 24)) + "\")");
    }
    if (s.peek() != '(') s.fail("expected '(' after " + name);
    s.advance();
    std::vector<double> args;
    while (s.peek() != ')') {
      if (s.atEnd()) s.fail("expected ')'");
      args.push_back(s.number(name.c_str()));
    }
    s.advance();
    s.skipSeparator();
    const auto count = [&](std::initializer_list<std::size_t> allowed) {
      for (std::size_t n : allowed) {
        if (args.size() == n) return;
      }
      s.fail(name + " takes " + std::to_string(*allowed.begin()) +
             (allowed.size() > 1 ? " or " + std::to_string(*(allowed.end() - 1)) : "") +
             " numbers, got " + std::to_string(args.size()));
    };
    SvgTransform t;
    if (name == "matrix") {
      count({6});
      t = {args[0], args[1], args[2], args[3], args[4], args[5]};
    } else if (name == "translate") {
      count({1, 2});
      t.e = args[0];
      t.f = args.size() > 1 ? args[1] : 0.0;
    } else if (name == "scale") {
      count({1, 2});
      t.a = args[0];
      t.d = args.size() > 1 ? args[1] : args[0];
    } else if (name == "rotate") {
      count({1, 3});
      const double r = args[0] * kSvgPi / 180.0;
      SvgTransform rot{std::cos(r), std::sin(r), -std::sin(r), std::cos(r), 0.0, 0.0};
      if (args.size() == 3) {
        const SvgTransform to{1, 0, 0, 1, args[1], args[2]};
        const SvgTransform back{1, 0, 0, 1, -args[1], -args[2]};
        rot = to.after(rot.after(back));
      }
      t = rot;
    } else if (name == "skewX") {
      count({1});
      t.c = std::tan(args[0] * kSvgPi / 180.0);
    } else if (name == "skewY") {
      count({1});
      t.b = std::tan(args[0] * kSvgPi / 180.0);
    } else {
      s.fail("unknown transform '" + name + "'");
    }
    total = total.after(t);  // the list applies right to left: the first is outermost
  }
  return total;
}

std::vector<std::vector<Eigen::Vector2d>> flattenSvgPath(std::string_view d, double tol,
                                                         std::size_t max_vertices) {
  SvgScanner s(d);
  RingBuilder out(max_vertices);
  Eigen::Vector2d cur = Eigen::Vector2d::Zero();
  Eigen::Vector2d start = cur;
  Eigen::Vector2d last_control = cur;  // reflected by S and T
  char last = 0;
  char command = 0;
  bool open = false;
  bool moved = false;
  while (!s.atEnd()) {
    const char c = s.peek();
    if (std::isalpha(static_cast<unsigned char>(c))) {
      if (std::string_view("MmLlHhVvCcSsQqTtAaZz").find(c) == std::string_view::npos) {
        s.fail(std::string("unknown path command '") + c + "'");
      }
      if (!moved && c != 'M' && c != 'm') s.fail("path data must start with a moveto (M or m)");
      moved = true;
      command = c;
      s.advance();
      s.skipSpace();
    } else if (!moved) {
      s.fail("path data must start with a moveto (M or m)");
    } else if (command == 0) {
      s.fail("numbers after a closepath (Z)");
    }
    // After a moveto, further pairs are linetos.
    const bool relative = std::islower(static_cast<unsigned char>(command));
    const Eigen::Vector2d base = relative ? cur : Eigen::Vector2d::Zero();
    const auto point = [&](const char* what) {
      const double x = s.number(what);
      const double y = s.number(what);
      return Eigen::Vector2d(x, y);
    };
    const char upper = static_cast<char>(std::toupper(static_cast<unsigned char>(command)));
    if (!open && upper != 'M' && upper != 'Z') {
      // A drawing command right after a closepath starts a new subpath at its start point.
      out.start(cur);
      open = true;
    }
    switch (upper) {
      case 'M': {
        cur = base + point("moveto");
        start = cur;
        out.start(cur);
        open = true;
        command = relative ? 'l' : 'L';
        last_control = cur;
        last = 'M';
        continue;
      }
      case 'L':
        cur = base + point("lineto");
        out.add(cur);
        break;
      case 'H':
        cur = {(relative ? cur.x() : 0.0) + s.number("horizontal lineto"), cur.y()};
        out.add(cur);
        break;
      case 'V':
        cur = {cur.x(), (relative ? cur.y() : 0.0) + s.number("vertical lineto")};
        out.add(cur);
        break;
      case 'C':
      case 'S': {
        // S reflects the last curve's second control point about the current point.
        const bool smooth = upper == 'S';
        const char* what = smooth ? "smooth curveto" : "curveto";
        const Eigen::Vector2d p1 = !smooth       ? Eigen::Vector2d(base + point(what))
                                   : last == 'C' ? Eigen::Vector2d(2 * cur - last_control)
                                                 : cur;
        const Eigen::Vector2d p2 = base + point(what);
        const Eigen::Vector2d p3 = base + point(what);
        cubic(out, cur, p1, p2, p3, tol);
        last_control = p2;
        cur = p3;
        last = 'C';
        continue;
      }
      case 'Q':
      case 'T': {
        // T reflects the last quadratic's control point.
        const bool smooth = upper == 'T';
        const Eigen::Vector2d p1 = !smooth ? Eigen::Vector2d(base + point("quadratic curveto"))
                                   : last == 'Q' ? Eigen::Vector2d(2 * cur - last_control)
                                                 : cur;
        const Eigen::Vector2d p2 =
            base + point(smooth ? "smooth quadratic curveto" : "quadratic curveto");
        quadratic(out, cur, p1, p2, tol);
        last_control = p1;
        cur = p2;
        last = 'Q';
        continue;
      }
      case 'A': {
        const double rx = s.number("arc radius");
        const double ry = s.number("arc radius");
        const double phi = s.number("arc rotation");
        const bool large = s.flag();
        const bool sweep = s.flag();
        const Eigen::Vector2d p = base + point("arc end point");
        arc(out, cur, rx, ry, phi, large, sweep, p, tol);
        cur = p;
        break;
      }
      case 'Z': {
        cur = start;
        out.finish();
        open = false;
        command = 0;
        last = 'Z';
        // A command letter (or the end) must follow.
        if (!s.atEnd() && !std::isalpha(static_cast<unsigned char>(s.peek()))) {
          s.fail("numbers after a closepath (Z)");
        }
        continue;
      }
      default: s.fail(std::string("unknown path command '") + command + "'");
    }
    last = upper;
    last_control = cur;
  }
  return out.take();
}

std::vector<Eigen::Vector2d> parseSvgPoints(std::string_view text) {
  SvgScanner s(text);
  std::vector<Eigen::Vector2d> points;
  while (!s.atEnd()) {
    const double x = s.number("x");
    if (s.atEnd()) s.fail("an odd count of numbers: the last point has no y");
    const double y = s.number("y");
    points.emplace_back(x, y);
  }
  return points;
}

std::vector<Eigen::Vector2d> svgEllipseArc(double cx, double cy, double rx, double ry, double a0,
                                           double a1, double tol) {
  const int n = arcChords(std::max(rx, ry), a1 - a0, tol);
  std::vector<Eigen::Vector2d> out;
  out.reserve(static_cast<std::size_t>(n) + 1);
  for (int i = 0; i <= n; ++i) {
    const double t = a0 + (a1 - a0) * i / n;
    out.emplace_back(cx + rx * std::cos(t), cy + ry * std::sin(t));
  }
  return out;
}

std::vector<Eigen::Vector2d> svgLineStroke(const std::vector<Eigen::Vector2d>& points, double width,
                                           const SvgTransform& to_lot) {
  // The line runs from the first point towards the farthest; every point projects onto it.
  const Eigen::Vector2d a = points.front();
  Eigen::Vector2d far = a;
  for (const Eigen::Vector2d& p : points) {
    if ((p - a).squaredNorm() > (far - a).squaredNorm()) far = p;
  }
  if (far == a) return {};
  const Eigen::Vector2d u = (far - a).normalized();
  const Eigen::Vector2d n(-u.y(), u.x());
  double lo = 0.0;
  double hi = 0.0;
  for (const Eigen::Vector2d& p : points) {
    lo = std::min(lo, (p - a).dot(u));
    hi = std::max(hi, (p - a).dot(u));
  }
  const double h = 0.5 * width;
  std::vector<Eigen::Vector2d> quad = {
      to_lot.apply(a + (lo - h) * u - h * n), to_lot.apply(a + (hi + h) * u - h * n),
      to_lot.apply(a + (hi + h) * u + h * n), to_lot.apply(a + (lo - h) * u + h * n)};
  double area = 0.0;
  for (std::size_t i = 0; i < quad.size(); ++i) {
    const Eigen::Vector2d& p = quad[i];
    const Eigen::Vector2d& q = quad[(i + 1) % quad.size()];
    area += p.x() * q.y() - q.x() * p.y();
  }
  if (!std::isfinite(area) || area == 0.0) return {};
  if (area < 0.0) std::reverse(quad.begin(), quad.end());
  return quad;
}

}  // namespace parksim
