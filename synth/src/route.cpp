#include "sextant/synth/route.hpp"
#include "sextant/core/units.hpp"

#include <algorithm>
#include <cmath>

namespace sextant::synth {
namespace {

/// A straight line or a circular arc of the route.
struct Piece {
  bool arc = false;
  Eigen::Vector2d start = Eigen::Vector2d::Zero();      ///< line start, or arc centre
  Eigen::Vector2d dir = Eigen::Vector2d::UnitX();       ///< line direction
  double radius = 0.0, start_angle = 0.0, sense = 1.0;  ///< arc: angle of the start point, +1 = left turn
  double length = 0.0;

  RoutePoint at(double s) const {
    if (!arc) return {start + s * dir, std::atan2(dir.y(), dir.x())};
    const double angle = start_angle + sense * s / radius;
    return {start + radius * Eigen::Vector2d(std::cos(angle), std::sin(angle)), angle + sense * 0.5 * kPi};
  }
};

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

std::vector<Piece> build_pieces(const std::vector<Eigen::Vector2d>& pts, double radius) {
  std::vector<Piece> pieces;
  Eigen::Vector2d cursor = pts.front();
  for (std::size_t i = 1; i < pts.size(); ++i) {
    const Eigen::Vector2d d_in = (pts[i] - pts[i - 1]).normalized();
    Eigen::Vector2d line_end = pts[i];
    Piece corner;
    // Vertex 1 is the turn on the spot (no fillet); the final vertex ends the route.
    if (i + 1 < pts.size() && i != 1 && radius > 0.0) {
      const Eigen::Vector2d d_out = (pts[i + 1] - pts[i]).normalized();
      const double cross = d_in.x() * d_out.y() - d_in.y() * d_out.x();
      const double turn = std::atan2(cross, d_in.dot(d_out));
      if (std::abs(turn) > 1e-6) {
        const double tangent = radius * std::tan(0.5 * std::abs(turn));
        line_end = pts[i] - tangent * d_in;
        const double sense = turn > 0 ? 1.0 : -1.0;
        const Eigen::Vector2d left(-d_in.y(), d_in.x());
        corner.arc = true;
        corner.radius = radius;
        corner.sense = sense;
        corner.start = line_end + sense * radius * left;
        const Eigen::Vector2d from_centre = line_end - corner.start;
        corner.start_angle = std::atan2(from_centre.y(), from_centre.x());
        corner.length = radius * std::abs(turn);
      }
    }
    Piece line;
    line.start = cursor;
    line.dir = d_in;
    line.length = std::max(0.0, (line_end - cursor).dot(d_in));
    pieces.push_back(line);
    if (corner.arc) {
      pieces.push_back(corner);
      cursor = corner.at(corner.length).position;
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

double start_leg_length(const WorldSettings& world, const TrajectorySettings& trajectory) {
  // Place the sharp turn half-way between scans 3 and 4: the approach is 3.5 steps long.
  const double sharp = trajectory.sharp_turn_deg * kPi / 180.0;
  auto pts = waypoints(world, 1.0, sharp);
  pts.erase(pts.begin());  // the route without its approach leg
  const double rest = total_length(build_pieces(pts, trajectory.corner_radius));
  if (trajectory.scans < 10) return 11.0;
  return 3.5 * rest / (trajectory.scans - 1 - 3.5);
}

std::vector<RoutePoint> sample_route(const WorldSettings& world, const TrajectorySettings& trajectory,
                                     Rng& rng) {
  const double sharp = trajectory.sharp_turn_deg * kPi / 180.0;
  const auto pieces =
      build_pieces(waypoints(world, start_leg_length(world, trajectory), sharp), trajectory.corner_radius);
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
