#include "sextant/synth/route.hpp"
#include "sextant/core/units.hpp"

#include <algorithm>
#include <cmath>

namespace sextant::synth {
namespace {

/// A straight line, a circular arc or a clothoid (curvature changing linearly with the distance) of the
/// route.
struct Piece {
  enum Kind { line, arc, clothoid } kind = line;
  Eigen::Vector2d start = Eigen::Vector2d::Zero();      ///< line or clothoid start, or arc centre
  Eigen::Vector2d dir = Eigen::Vector2d::UnitX();       ///< line direction
  double radius = 0.0, start_angle = 0.0, sense = 1.0;  ///< arc: angle of the start point, +1 = left turn
  double heading = 0.0, curvature = 0.0, curvature_rate = 0.0;  ///< clothoid: at its start [rad, 1/m, 1/m²]
  double length = 0.0;

  RoutePoint at(double s) const {
    if (kind == line) return {start + s * dir, std::atan2(dir.y(), dir.x())};
    if (kind == arc) {
      const double angle = start_angle + sense * s / radius;
      return {start + radius * Eigen::Vector2d(std::cos(angle), std::sin(angle)), angle + sense * 0.5 * kPi};
    }
    const auto heading_at = [&](double u) { return heading + curvature * u + 0.5 * curvature_rate * u * u; };
    // The position is the integral of the heading's direction (Fresnel integrals), by Simpson's rule on
    // ≤ 5 cm intervals: the integrand's fourth derivative is ~κ⁴, so the error is far below a µm.
    const int n = 2 * std::max(4, static_cast<int>(std::ceil(s / 0.1)));
    const double h = s / n;
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    for (int j = 0; j <= n; ++j) {
      const double weight = j == 0 || j == n ? 1.0 : (j % 2 == 1 ? 4.0 : 2.0);
      const double a = heading_at(j * h);
      sum += weight * Eigen::Vector2d(std::cos(a), std::sin(a));
    }
    return {start + (h / 3.0) * sum, heading_at(s)};
  }
};

/// The clothoid that eases a left turn in: from heading 0 and curvature 0 at the origin to curvature
/// 1 / radius after `transition` metres.
Piece easing_in(double radius, double transition) {
  Piece p;
  p.kind = Piece::clothoid;
  p.curvature_rate = 1.0 / (radius * transition);
  p.length = transition;
  return p;
}

/// The route's corner points: an approach leg, then four loops over the 2×2 blocks.
std::vector<Eigen::Vector2d> waypoints(const WorldSettings& w, double start_leg, double sharp_turn) {
  const double L = w.block_length, W = w.block_width;
  const Eigen::Vector2d approach(std::cos(-sharp_turn), std::sin(-sharp_turn));
  return {-start_leg * approach,
          {0, 0},
          // loop 1: around the south-west block
          {L, 0},
          {L, W},
          {0, W},
          {0, 0},
          // loop 2: around the whole campus
          {2 * L, 0},
          {2 * L, 2 * W},
          {0, 2 * W},
          {0, 0},
          // loop 3: through the middle, back along the first loop's road
          {L, 0},
          {L, 2 * W},
          {0, 2 * W},
          {0, W},
          {2 * L, W},
          // loop 4: round the north and home to the start
          {2 * L, 2 * W},
          {0, 2 * W},
          {0, 0}};
}

/// The pieces easing a left turn of `turn` in and out (clothoid, arc, clothoid), from the origin heading
/// along +x: of the turn, each clothoid takes transition / (2 radius) (Ls / 2R, its heading's change).
std::vector<Piece> eased_left_turn(double radius, double transition, double turn) {
  Piece in = easing_in(radius, transition);
  const RoutePoint in_end = in.at(in.length);
  Piece middle;
  middle.kind = Piece::arc;
  middle.radius = radius;
  const Eigen::Vector2d centre =
      in_end.position + radius * Eigen::Vector2d(-std::sin(in_end.heading), std::cos(in_end.heading));
  middle.start = centre;
  middle.start_angle = std::atan2(in_end.position.y() - centre.y(), in_end.position.x() - centre.x());
  middle.length = std::max(0.0, radius * turn - transition);
  const RoutePoint middle_end = middle.at(middle.length);
  Piece out;
  out.kind = Piece::clothoid;
  out.start = middle_end.position;
  out.heading = middle_end.heading;
  out.curvature = 1.0 / radius;
  out.curvature_rate = -in.curvature_rate;
  out.length = transition;
  return {in, middle, out};
}

/// `pieces` (of a left turn from the origin along +x) turned the way `sense` says (+1 left, −1 right)
/// and placed at `origin` heading along `dir`.
std::vector<Piece> placed(std::vector<Piece> pieces, double sense, const Eigen::Vector2d& origin,
                          const Eigen::Vector2d& dir) {
  const double heading = std::atan2(dir.y(), dir.x());
  const Eigen::Rotation2Dd turn(heading);
  for (Piece& p : pieces) {
    p.start = origin + turn * Eigen::Vector2d(p.start.x(), sense * p.start.y());
    if (p.kind == Piece::arc) {
      p.sense = sense;
      p.start_angle = heading + sense * p.start_angle;
    } else {
      p.heading = heading + sense * p.heading;
      p.curvature *= sense;
      p.curvature_rate *= sense;
    }
  }
  return pieces;
}

std::vector<Piece> build_pieces(const std::vector<Eigen::Vector2d>& pts, double radius, double transition) {
  std::vector<Piece> pieces;
  Eigen::Vector2d cursor = pts.front();
  for (std::size_t i = 1; i < pts.size(); ++i) {
    const Eigen::Vector2d d_in = (pts[i] - pts[i - 1]).normalized();
    Eigen::Vector2d line_end = pts[i];
    std::vector<Piece> corner;
    // Vertex 1 is the turn on the spot (no fillet); the final vertex ends the route.
    if (i + 1 < pts.size() && i != 1 && radius > 0.0) {
      const Eigen::Vector2d d_out = (pts[i + 1] - pts[i]).normalized();
      const double cross = d_in.x() * d_out.y() - d_in.y() * d_out.x();
      const double turn = std::atan2(cross, d_in.dot(d_out));
      if (std::abs(turn) > 1e-6) {
        const double tangent = corner_tangent_length(radius, transition, std::abs(turn));
        line_end = pts[i] - tangent * d_in;
        const double sense = turn > 0 ? 1.0 : -1.0;
        if (transition > 0.0) {
          corner =
              placed(eased_left_turn(radius, std::min(transition, radius * std::abs(turn)), std::abs(turn)),
                     sense, line_end, d_in);
        } else {
          Piece arc;
          const Eigen::Vector2d left(-d_in.y(), d_in.x());
          arc.kind = Piece::arc;
          arc.radius = radius;
          arc.sense = sense;
          arc.start = line_end + sense * radius * left;
          const Eigen::Vector2d from_centre = line_end - arc.start;
          arc.start_angle = std::atan2(from_centre.y(), from_centre.x());
          arc.length = radius * std::abs(turn);
          corner.push_back(arc);
        }
      }
    }
    Piece line;
    line.start = cursor;
    line.dir = d_in;
    line.length = std::max(0.0, (line_end - cursor).dot(d_in));
    pieces.push_back(line);
    if (!corner.empty()) {
      pieces.insert(pieces.end(), corner.begin(), corner.end());
      cursor = corner.back().at(corner.back().length).position;
    } else {
      cursor = line_end;
    }
  }
  return pieces;
}

double total_length(const std::vector<Piece>& pieces) {
  double total = 0.0;
  for (const auto& p : pieces) total += p.length;
  return total;
}

}  // namespace

double corner_tangent_length(double radius, double transition, double turn) {
  if (transition <= 0.0) return radius * std::tan(0.5 * turn);
  transition = std::min(transition, radius * turn);
  // The clothoid's end (x, y) and heading τ = Ls / 2R: the arc is shifted off the lines by
  // p = y − R (1 − cos τ) and starts k = x − R sin τ past the clothoid's start.
  const Piece in = easing_in(radius, transition);
  const RoutePoint end = in.at(in.length);
  const double p = end.position.y() - radius * (1.0 - std::cos(end.heading));
  const double k = end.position.x() - radius * std::sin(end.heading);
  return (radius + p) * std::tan(0.5 * turn) + k;
}

double start_leg_length(const WorldSettings& world, const TrajectorySettings& trajectory) {
  // Place the sharp turn half-way between scans 3 and 4: the approach is 3.5 steps long.
  const double sharp = trajectory.sharp_turn_deg * kPi / 180.0;
  auto pts = waypoints(world, 1.0, sharp);
  pts.erase(pts.begin());  // the route without its approach leg
  const double rest = total_length(build_pieces(pts, trajectory.corner_radius, trajectory.corner_transition));
  if (trajectory.scans < 10) return 11.0;
  return 3.5 * rest / (trajectory.scans - 1 - 3.5);
}

std::vector<RoutePoint> sample_route(const WorldSettings& world, const TrajectorySettings& trajectory,
                                     Rng& rng) {
  const double sharp = trajectory.sharp_turn_deg * kPi / 180.0;
  const auto pieces = build_pieces(waypoints(world, start_leg_length(world, trajectory), sharp),
                                   trajectory.corner_radius, trajectory.corner_transition);
  const double total = total_length(pieces);
  const double wander_phase = rng.uniform(0.0, 2 * kPi);
  std::vector<RoutePoint> out;
  const int n = trajectory.scans;
  std::size_t piece = 0;
  double piece_start = 0.0;
  for (int i = 0; i < n; ++i) {
    const double s = n > 1 ? total * i / (n - 1) : 0.0;
    while (piece + 1 < pieces.size() && s >= piece_start + pieces[piece].length) {
      piece_start += pieces[piece].length;
      ++piece;
    }
    RoutePoint p = pieces[piece].at(std::min(s - piece_start, pieces[piece].length));
    // Slow sideways wander within the lane (zero at the start).
    const double wander = trajectory.lateral_wander * std::sin(2 * kPi * s / 97.0 + wander_phase) -
                          trajectory.lateral_wander * std::sin(wander_phase);
    p.position += wander * Eigen::Vector2d(-std::sin(p.heading), std::cos(p.heading));
    out.push_back(p);
  }
  return out;
}

Eigen::Isometry3d ground_following_pose(const World& world, const TrajectorySettings& trajectory,
                                        const RoutePoint& point) {
  const Eigen::Vector2d f(std::cos(point.heading), std::sin(point.heading));
  const Eigen::Vector2d l(-f.y(), f.x());
  const Eigen::Vector2d& p = point.position;
  const auto h = [&](const Eigen::Vector2d& q) { return world.ground_height(q.x(), q.y()); };
  const double half_base = 0.5 * trajectory.wheelbase, half_track = 0.5 * trajectory.track;
  const double rise_forward = h(p + half_base * f) - h(p - half_base * f);
  const double rise_left = h(p + half_track * l) - h(p - half_track * l);
  const Eigen::Vector3d x_axis =
      Eigen::Vector3d(f.x(), f.y(), rise_forward / trajectory.wheelbase).normalized();
  const Eigen::Vector3d left(l.x(), l.y(), rise_left / trajectory.track);
  const Eigen::Vector3d z_axis = x_axis.cross(left).normalized();
  const Eigen::Vector3d y_axis = z_axis.cross(x_axis);
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear().col(0) = x_axis;
  T.linear().col(1) = y_axis;
  T.linear().col(2) = z_axis;
  T.translation() = Eigen::Vector3d(p.x(), p.y(), h(p)) + trajectory.sensor_height * z_axis;
  return T;
}

Eigen::Matrix3d handheld_sway(const TrajectorySettings& trajectory, std::size_t index) {
  if (trajectory.platform != "handheld") return Eigen::Matrix3d::Identity();
  const double i = static_cast<double>(index);
  const double yaw =
      trajectory.look_around_deg * kRadPerDeg * std::sin(2.0 * kPi * i / trajectory.look_around_scans);
  const double sway = trajectory.sway_deg * kRadPerDeg;
  const double roll = sway * std::sin(2.0 * kPi * i / 5.3),
               pitch = sway * std::sin(2.0 * kPi * i / 7.1 + 1.0);
  return (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

}  // namespace sextant::synth
