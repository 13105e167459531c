#include "navigation_core/footprint.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <system_error>

namespace navigation_core {
namespace {

double sign0(double v) { return v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0); }

// Distance from the origin to the segment a-b.
double distanceToSegment(const Point2& a, const Point2& b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double length2 = dx * dx + dy * dy;
  double t = length2 > 0 ? -(a.x * dx + a.y * dy) / length2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(a.x + t * dx, a.y + t * dy);
}

// A reader over the footprint text that says where it stopped making sense.
class Reader {
 public:
  explicit Reader(const std::string& text) : text_(text) {}

  void skipSpace() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  bool accept(char c) {
    skipSpace();
    if (pos_ < text_.size() && text_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }
  void expect(char c, const char* what) {
    if (!accept(c)) fail(std::string("expected ") + what);
  }
  double number() {
    skipSpace();
    const char* start = text_.data() + pos_;
    if (pos_ < text_.size() && text_[pos_] == '+') ++start;  // from_chars takes no '+'
    double value = 0.0;
    const auto [end, error] = std::from_chars(start, text_.data() + text_.size(), value);  // whatever the locale
    if (error != std::errc() || !std::isfinite(value)) fail("expected a number");
    pos_ = static_cast<std::size_t>(end - text_.data());
    return value;
  }
  bool atEnd() {
    skipSpace();
    return pos_ == text_.size();
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw std::invalid_argument("footprint '" + text_ + "': " + what + " at character " + std::to_string(pos_ + 1) +
                                " (expected the form [[x1, y1], [x2, y2], [x3, y3], ...])");
  }

 private:
  const std::string& text_;
  std::size_t pos_ = 0;
};

}  // namespace

Footprint footprintFromRadius(double radius) {
  constexpr int kPoints = 16;
  Footprint points;
  for (int i = 0; i < kPoints; ++i) {
    const double angle = i * 2.0 * M_PI / kPoints;
    points.push_back({radius * std::cos(angle), radius * std::sin(angle)});
  }
  return points;
}

Footprint padFootprint(Footprint footprint, double padding) {
  for (Point2& p : footprint) {
    p.x += sign0(p.x) * padding;
    p.y += sign0(p.y) * padding;
  }
  return footprint;
}

FootprintRadii footprintRadii(const Footprint& footprint) {
  FootprintRadii r;
  if (footprint.empty()) return r;
  r.inscribed = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < footprint.size(); ++i) {
    const Point2& a = footprint[i];
    const Point2& b = footprint[(i + 1) % footprint.size()];
    r.inscribed = std::min({r.inscribed, std::hypot(a.x, a.y), distanceToSegment(a, b)});
    r.circumscribed = std::max(r.circumscribed, std::hypot(a.x, a.y));
  }
  return r;
}

Footprint parseFootprint(const std::string& text) {
  Reader in(text);
  Footprint points;
  in.expect('[', "'[' opening the list of points");
  if (!in.accept(']')) {
    do {
      in.expect('[', "'[' opening a point");
      Point2 p;
      p.x = in.number();
      in.expect(',', "',' between a point's x and y");
      p.y = in.number();
      in.expect(']', "']' closing a point after its two numbers");
      points.push_back(p);
    } while (in.accept(','));
    in.expect(']', "',' or ']' after a point");
  }
  if (!in.atEnd()) in.fail("expected nothing after the closing ']'");
  if (points.size() < 3)
    throw std::invalid_argument("footprint '" + text + "': expected at least three points, got " +
                                std::to_string(points.size()));
  return points;
}

}  // namespace navigation_core
