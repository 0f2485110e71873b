#include "report/motion_geometry.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "physics/boat_frame.hpp"

namespace bb::motion {

namespace {

/// What a body reaches from its centre (metres).
double extent(const Body& body) {
  if (body.shape == Shape::Sphere) return body.radius;
  if (body.shape == Shape::Box) return body.half_extents.norm();
  return 0.0;
}

/// A box's corners at `state`, projected: 4 (2D, in order round the box) or 8 (3D, corner i
/// at the signs of bits 0, 1, 2 of i).
std::vector<Point2> box_corners(const Scene& scene, const Body& body, const BodyState& state) {
  std::vector<Point2> out;
  const Vec3& h = body.half_extents;
  if (scene.dims == 2) {
    for (const auto& [sx, sy] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}})
      out.push_back(
          project(scene, state.position + state.orientation * Vec3(sx * h.x(), sy * h.y(), 0.0)));
    return out;
  }
  for (int i = 0; i < 8; ++i)
    out.push_back(
        project(scene, state.position + state.orientation * Vec3((i & 1 ? 1 : -1) * h.x(),
                                                                 (i & 2 ? 1 : -1) * h.y(),
                                                                 (i & 4 ? 1 : -1) * h.z())));
  return out;
}

/// A boat seen from above: its hull pointed at the bow (the heading, the body's x axis),
/// then its sail as a line from the mast, a third of the way to the bow, out to leeward at
/// the sail's angle from the heading (physics/sail_term.cpp: the boom swings to the side
/// the apparent wind blows towards).
std::string boat_path(const Scene& scene, const Body& body, const BodyState& state,
                      const Canvas& c) {
  const BoatFrame frame = boat_frame(state.orientation);
  const double hx = body.half_extents.x(), hy = body.half_extents.y();
  const auto at = [&](double ahead, double across) {
    return c.px(project(scene, state.position + ahead * frame.ahead + across * frame.across));
  };
  const Point2 hull[] = {at(-hx, -hy), at(0.3 * hx, -hy), at(hx, 0.0), at(0.3 * hx, hy),
                         at(-hx, hy)};
  std::string d = fmt::format("M{} {}", num(hull[0].x), num(hull[0].y));
  for (int i = 1; i < 5; ++i) d += fmt::format(" L{} {}", num(hull[i].x), num(hull[i].y));
  const Vec3 wind = scene.air ? scene.air->wind : Vec3::Zero();
  const double side = (wind - state.velocity).dot(frame.across) > 0.0 ? -1.0 : 1.0;
  const double angle = body.sail->angle * std::numbers::pi / 180.0;
  const double boom = 1.2 * hx;
  const Point2 mast = at(hx / 3.0, 0.0);
  const Point2 clew = at(hx / 3.0 - boom * std::cos(angle), -side * boom * std::sin(angle));
  return d + fmt::format(" Z M{} {} L{} {}", num(mast.x), num(mast.y), num(clew.x), num(clew.y));
}

}  // namespace

bool is_boat(const Scene& scene, const Body& body) {
  return scene.dims == 2 && body.shape == Shape::Box && body.sail.has_value();
}

std::string wind_svg(const Scene& scene, const Canvas& c, double thick) {
  if (!scene.air || scene.air->wind.norm() == 0.0) return "";
  const Point2 w = project(scene, scene.air->wind);
  const double norm = std::hypot(w.x, w.y);
  if (norm == 0.0) return "";
  // On the page y points down; an arrow 50 pixels long about a point in the top left.
  const double half = 25 * thick;
  const Point2 d{w.x / norm, -w.y / norm}, mid{std::min(2 * half, c.width / 2), 1.8 * half};
  const Point2 tail{mid.x - half * d.x, mid.y - half * d.y};
  const Point2 tip{mid.x + half * d.x, mid.y + half * d.y};
  const auto barb = [&](double turn) {
    const double ca = std::cos(turn), sa = std::sin(turn);
    return Point2{tip.x - 0.4 * half * (ca * d.x - sa * d.y),
                  tip.y - 0.4 * half * (sa * d.x + ca * d.y)};
  };
  const Point2 b1 = barb(0.45), b2 = barb(-0.45);
  return fmt::format(
      "<g class=\"wind\" stroke=\"#2f6db5\" stroke-width=\"{:.1f}\" fill=\"none\"><path d=\"M{} "
      "{} L{} {} M{} {} L{} {} L{} {}\"/><text x=\"{}\" y=\"{}\" fill=\"#2f6db5\" "
      "stroke=\"none\" font-size=\"{:.1f}\" text-anchor=\"middle\">wind {:.3g} m/s</text></g>\n",
      2.5 * thick, num(tail.x), num(tail.y), num(tip.x), num(tip.y), num(b1.x), num(b1.y),
      num(tip.x), num(tip.y), num(b2.x), num(b2.y), num(mid.x), num(mid.y + 1.7 * half), 12 * thick,
      scene.air->wind.norm());
}

Point2 project(const Scene& scene, const Vec3& p) {
  if (scene.dims == 2) return {p.x(), p.y()};
  return {p.x() + 0.4330127018922193 * p.z(), p.y() + 0.25 * p.z()};
}

std::string num(double v) {
  return fmt::format("{:.1f}", v);
}

Canvas fit(const Scene& scene, const std::vector<const Trajectory*>& framed,
           const std::vector<int>& drawn, double width, double min_height, double max_height) {
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  const auto add = [&](Point2 p, double r) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return;
    x0 = std::min(x0, p.x - r), x1 = std::max(x1, p.x + r);
    y0 = std::min(y0, p.y - r), y1 = std::max(y1, p.y + r);
  };
  for (const Trajectory* run : framed)
    for (const State& s : run->states)
      for (std::size_t k = 0; k < drawn.size() && k < s.size(); ++k)
        add(project(scene, s[k].position), extent(scene.bodies[drawn[k]]));
  for (const Body& b : scene.bodies)
    if (b.fixed) add(project(scene, b.position), extent(b));
  if (scene.ground) add(project(scene, scene.ground->point), 0.0);
  if (x0 > x1) x0 = -1, x1 = 1, y0 = -1, y1 = 1;
  // A margin, and never less than a metre across.
  const double span = std::max({x1 - x0, y1 - y0, 1.0});
  const double margin = 0.08 * span;
  x0 -= margin, x1 += margin, y0 -= margin, y1 += margin;
  Canvas c;
  c.width = width;
  c.scale = width / (x1 - x0);
  c.height = std::clamp((y1 - y0) * c.scale, min_height, max_height);
  if ((y1 - y0) * c.scale > max_height) {
    // Too tall: the scale comes from the height, and the world shown widens about its middle.
    c.scale = max_height / (y1 - y0);
    x0 -= (width / c.scale - (x1 - x0)) / 2;
  }
  c.x0 = x0;
  // The world centred vertically in the canvas.
  c.y1 = (y0 + y1) / 2 + c.height / c.scale / 2;
  return c;
}

std::string ground_svg(const Scene& scene, const Canvas& c) {
  if (!scene.ground) return "";
  const Vec3& n = scene.ground->normal;
  const Point2 p = c.px(project(scene, scene.ground->point));
  // On the page (y down) the ground's line runs along (n.y, n.x) and below it is (-n.x, n.y).
  Point2 along{n.y(), n.x()}, down{-n.x(), n.y()};
  const double norm = std::hypot(along.x, along.y);
  if (norm < 1e-9) return "";  // a ground facing the viewer: nothing to draw as a line
  along.x /= norm, along.y /= norm, down.x /= norm, down.y /= norm;
  const double far = 4.0 * (c.width + c.height);
  const Point2 a{p.x - far * along.x, p.y - far * along.y};
  const Point2 b{p.x + far * along.x, p.y + far * along.y};
  return fmt::format(
      "<path d=\"M{} {} L{} {} L{} {} L{} {} Z\" fill=\"#efe6d6\" stroke=\"none\"/>\n"
      "<path d=\"M{} {} L{} {}\" stroke=\"#6b5a3e\" stroke-width=\"2\"/>\n",
      num(a.x), num(a.y), num(b.x), num(b.y), num(b.x + far * down.x), num(b.y + far * down.y),
      num(a.x + far * down.x), num(a.y + far * down.y), num(a.x), num(a.y), num(b.x), num(b.y));
}

Outline outline(const Scene& scene, const Body& body, const BodyState& state, const Canvas& c,
                bool mark_turn) {
  Outline o;
  if (is_boat(scene, body)) {
    o.path = boat_path(scene, body, state, c);
    return o;
  }
  if (body.shape == Shape::Box) {
    std::vector<Point2> p;
    for (const Point2& q : box_corners(scene, body, state)) p.push_back(c.px(q));
    if (p.size() == 4) {
      o.path = fmt::format("M{} {} L{} {} L{} {} L{} {} Z", num(p[0].x), num(p[0].y), num(p[1].x),
                           num(p[1].y), num(p[2].x), num(p[2].y), num(p[3].x), num(p[3].y));
    } else {
      // The twelve edges: corners that differ in one sign.
      for (int i = 0; i < 8; ++i)
        for (int bit : {1, 2, 4})
          if (!(i & bit))
            o.path += fmt::format("M{} {} L{} {} ", num(p[i].x), num(p[i].y), num(p[i | bit].x),
                                  num(p[i | bit].y));
    }
    return o;
  }
  o.circle = true;
  o.centre = c.px(project(scene, state.position));
  o.radius = body.shape == Shape::Sphere ? std::max(c.len(body.radius), 2.0) : 3.0;
  if (mark_turn && body.shape == Shape::Sphere) {
    // A radius along the body's own x axis shows how it has turned.
    const Point2 rim =
        c.px(project(scene, state.position + state.orientation * Vec3(body.radius, 0.0, 0.0)));
    o.path = fmt::format("M{} {} L{} {}", num(o.centre.x), num(o.centre.y), num(rim.x), num(rim.y));
  }
  return o;
}

std::string fixed_svg(const Scene& scene, const Canvas& c) {
  std::string out;
  for (const Body& b : scene.bodies) {
    if (!b.fixed) continue;
    BodyState s;
    s.position = b.position;
    s.orientation = b.orientation;
    const Outline o = outline(scene, b, s, c, false);
    out += o.circle ? fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"#8a8a8a\"/>\n",
                                  num(o.centre.x), num(o.centre.y), num(o.radius))
                    : fmt::format("<path d=\"{}\" fill=\"#8a8a8a\" stroke=\"#555555\"/>\n", o.path);
  }
  for (const Hinge& h : scene.hinges) {
    const Point2 p = c.px(project(scene, h.anchor));
    out += fmt::format(
        "<circle cx=\"{}\" cy=\"{}\" r=\"4\" fill=\"#ffffff\" stroke=\"#000000\" "
        "stroke-width=\"1.5\"/>\n",
        num(p.x), num(p.y));
  }
  return out;
}

std::vector<std::pair<std::size_t, std::size_t>> drawn_springs(const Scene& scene,
                                                               const std::vector<int>& drawn) {
  std::vector<int> slot(scene.bodies.size(), -1);
  for (std::size_t k = 0; k < drawn.size(); ++k) slot[drawn[k]] = static_cast<int>(k);
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (const Spring& s : scene.springs)
    if (slot[s.body_a] >= 0 && slot[s.body_b] >= 0)
      out.emplace_back(static_cast<std::size_t>(slot[s.body_a]),
                       static_cast<std::size_t>(slot[s.body_b]));
  return out;
}

std::string springs_path(const Scene& scene, const State& s,
                         const std::vector<std::pair<std::size_t, std::size_t>>& springs,
                         const Canvas& c) {
  std::string d;
  for (const auto& [a, b] : springs) {
    if (a >= s.size() || b >= s.size()) continue;
    const Point2 p = c.px(project(scene, s[a].position));
    const Point2 q = c.px(project(scene, s[b].position));
    d += fmt::format("M{} {} L{} {} ", num(p.x), num(p.y), num(q.x), num(q.y));
  }
  return d;
}

}  // namespace bb::motion
