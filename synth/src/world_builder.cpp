#include "sextant/synth/world_builder.hpp"
#include "sextant/core/units.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "world_geometry.hpp"

namespace sextant::synth {
namespace {

using namespace detail;  // NOLINT: the builder's own geometry helpers

class Builder {
 public:
  Builder(const WorldSettings& s, double start_clearance, Rng& rng)
      : s_(s), start_clearance_(start_clearance), rng_(rng) {}

  World build() {
    const double L = s_.block_length, W = s_.block_width;
    world_.min = {-s_.border, -s_.border};
    world_.max = {2 * L + s_.border, 2 * W + s_.border};
    world_.foliage_porosity = s_.foliage_porosity;
    world_.foliage_penetration = s_.foliage_penetration;
    build_ground(s_, rng_, world_);
    build_roadside();
    for (const Rect& lot : lots()) fill_lot(lot);
    world_.build_grid(s_.grid_cell);
    return std::move(world_);
  }

 private:
  // Uniform draws in [lo, hi) per axis, the last axis drawn first: the order GCC gave the
  // unsequenced constructor arguments these replace, so the campus stays what it was.
  Eigen::Vector3d reversed_draws(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
    Eigen::Vector3d v;
    for (int a = 2; a >= 0; --a) v(a) = rng_.uniform(lo(a), hi(a));
    return v;
  }

  double ground(double x, double y) const { return world_.ground_height(x, y); }

  // ---- roads: kerbs, parked cars, poles, trees ---------------------------------------------
  bool near_crossing(double along, double crossing_spacing, int crossings, double clearance) const {
    for (int c = 0; c < crossings; ++c)
      if (std::abs(along - c * crossing_spacing) < clearance) return true;
    return false;
  }

  void build_roadside() {
    const double L = s_.block_length, W = s_.block_width;
    // Horizontal roads (along x) at y = 0, W, 2W; vertical roads (along y) at x = 0, L, 2L.
    for (int r = 0; r < 3; ++r) {
      road(Eigen::Vector2d(0, r * W), Eigen::Vector2d(1, 0), 2 * L, L);
      road(Eigen::Vector2d(r * L, 0), Eigen::Vector2d(0, 1), 2 * W, W);
    }
  }

  void road(const Eigen::Vector2d& start, const Eigen::Vector2d& dir, double length,
            double crossing_spacing) {
    const Eigen::Vector2d left(-dir.y(), dir.x());
    const double yaw = std::atan2(dir.y(), dir.x());
    const double rhw = s_.road_half_width;
    for (const double side : {-1.0, 1.0}) {
      // Kerbs: 2 m segments, gaps at the crossings.
      if (s_.kerb_height > 0.0) {
        for (double a = 1.0; a < length; a += 2.0) {
          if (near_crossing(a, crossing_spacing, 3, rhw + 1.0)) continue;
          const Eigen::Vector2d p = start + a * dir + side * (rhw + 0.1) * left;
          const double g = ground(p.x(), p.y());
          add(OrientedBox{{p.x(), p.y(), g + 0.5 * (s_.kerb_height - 0.15)},
                          {1.0, 0.1, 0.5 * (s_.kerb_height + 0.15)},
                          yaw},
              ObjectKind::kKerb);
        }
      }
      // Parked cars at the road edge.
      for (double a = rng_.uniform(0, s_.car_spacing); a < length;
           a += s_.car_spacing * rng_.uniform(0.6, 1.4)) {
        if (near_crossing(a, crossing_spacing, 3, kCrossingClearance)) continue;
        if (rng_.uniform() < 0.3) continue;  // free space
        add_car(start + a * dir + side * (rhw - 1.1) * left, yaw + rng_.normal(0.0, 0.03));
      }
      // Poles on the sidewalk.
      for (double a = rng_.uniform(0, s_.pole_spacing); a < length;
           a += s_.pole_spacing * rng_.uniform(0.6, 1.4)) {
        if (near_crossing(a, crossing_spacing, 3, kCrossingClearance)) continue;
        const Eigen::Vector2d p = start + a * dir + side * (rhw + 0.8) * left;
        const double g = ground(p.x(), p.y());
        add(Cylinder{p, rng_.uniform(0.06, 0.14), g - 0.2, g + rng_.uniform(3.5, 8.0)}, ObjectKind::kPole);
      }
      // Trees behind the poles.
      for (double a = rng_.uniform(0, s_.tree_spacing); a < length;
           a += s_.tree_spacing * rng_.uniform(0.6, 1.4)) {
        if (near_crossing(a, crossing_spacing, 3, kCrossingClearance)) continue;
        add_tree(start + a * dir + side * (rhw + 2.0) * left);
      }
    }
  }

  void add_car(const Eigen::Vector2d& p, double yaw) {
    const double g = ground(p.x(), p.y());
    const double length = rng_.uniform(3.8, 4.8), width = rng_.uniform(1.65, 1.9),
                 body = rng_.uniform(0.7, 1.0);
    add(OrientedBox{{p.x(), p.y(), g + 0.25 + 0.5 * body}, {0.5 * length, 0.5 * width, 0.5 * body}, yaw},
        ObjectKind::kCar);
    const double cabin = rng_.uniform(0.45, 0.65);
    add(
        OrientedBox{
            {p.x(), p.y(), g + 0.25 + body + 0.5 * cabin}, {0.28 * length, 0.45 * width, 0.5 * cabin}, yaw},
        ObjectKind::kCar);
    footprint_box(p, 0.5 * length, 0.5 * width, yaw, ObjectKind::kCar);
  }

  void add_tree(const Eigen::Vector2d& p) {
    const double g = ground(p.x(), p.y());
    const double trunk = rng_.uniform(2.0, 3.5);
    add(Cylinder{p, rng_.uniform(0.12, 0.3), g - 0.2, g + trunk + 0.5}, ObjectKind::kTrunk);
    const int blobs = 3 + static_cast<int>(rng_.index(4));
    for (int b = 0; b < blobs; ++b) {
      const Eigen::Vector3d c =
          reversed_draws(Eigen::Vector3d(-1.2, -1.2, 0.6), Eigen::Vector3d(1.2, 1.2, 2.2)) +
          Eigen::Vector3d(p.x(), p.y(), g + trunk);
      add(Ellipsoid{c, {rng_.uniform(1.0, 2.0), rng_.uniform(1.0, 2.0), rng_.uniform(0.8, 1.3)}},
          ObjectKind::kFoliage);
    }
  }

  void add_bush(const Eigen::Vector2d& p) {
    const double g = ground(p.x(), p.y());
    const Eigen::Vector3d r = reversed_draws(Eigen::Vector3d(0.6, 0.6, 0.5), Eigen::Vector3d(1.6, 1.6, 1.0));
    add(Ellipsoid{{p.x(), p.y(), g + 0.6 * r.z()}, r}, ObjectKind::kFoliage);
  }

  // ---- lots: buildings, free-standing walls, bushes ------------------------------------------
  std::vector<Rect> lots() {
    const double L = s_.block_length, W = s_.block_width, b = s_.border;
    const double m = s_.road_half_width + kSidewalk;
    std::vector<Rect> areas;
    for (int bx = 0; bx < 2; ++bx)
      for (int by = 0; by < 2; ++by)
        areas.push_back({bx * L + m, by * W + m, (bx + 1) * L - m, (by + 1) * W - m});
    areas.push_back({-b + 2, -b + 2, 2 * L + b - 2, -m});                      // south
    areas.push_back({-b + 2, 2 * W + m, 2 * L + b - 2, 2 * W + b - 2});        // north
    areas.push_back({-b + 2, -m, -std::max(m, start_clearance_), 2 * W + m});  // west
    areas.push_back({2 * L + m, -m, 2 * L + b - 2, 2 * W + m});                // east
    std::vector<Rect> out;
    for (const Rect& a : areas) {
      if (a.width() < 6.0 || a.height() < 6.0) continue;
      const bool along_x = a.width() >= a.height();
      const double length = along_x ? a.width() : a.height();
      double pos = 0.0;
      while (pos < length - 8.0) {
        double w = rng_.uniform(13.0, 26.0);
        if (length - (pos + w) < 10.0) w = length - pos;
        const double lo = pos + 1.0, hi = pos + w - 1.0;
        out.push_back(along_x ? Rect{a.x0 + lo, a.y0, a.x0 + hi, a.y1}
                              : Rect{a.x0, a.y0 + lo, a.x1, a.y0 + hi});
        pos += w;
      }
    }
    return out;
  }

  void fill_lot(const Rect& lot) {
    if (rng_.uniform() < s_.building_probability && lot.width() >= 8.0 && lot.height() >= 8.0) {
      add_building(lot);
    } else {
      add_free_wall(lot);
      for (int t = 0; t < 2; ++t)
        add_tree({rng_.uniform(lot.x0 + 2, lot.x1 - 2), rng_.uniform(lot.y0 + 2, lot.y1 - 2)});
    }
    for (int k = 0; k < s_.bushes_per_lot; ++k) {
      // Bushes along the lot's edges (gardens in front of the buildings).
      const double u = rng_.uniform();
      const bool horizontal = rng_.uniform() < 0.5;
      const Eigen::Vector2d p =
          horizontal ? Eigen::Vector2d(lot.x0 + u * lot.width(), rng_.uniform() < 0.5 ? lot.y0 : lot.y1)
                     : Eigen::Vector2d(rng_.uniform() < 0.5 ? lot.x0 : lot.x1, lot.y0 + u * lot.height());
      add_bush(p);
    }
  }

  double min_ground(const std::vector<Eigen::Vector3d>& outline) const {
    double g = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < outline.size(); ++i) {
      const Eigen::Vector3d& a = outline[i];
      const Eigen::Vector3d& b = outline[(i + 1) % outline.size()];
      for (int k = 0; k <= 8; ++k) {
        const Eigen::Vector3d p = a + (b - a) * (k / 8.0);
        g = std::min(g, ground(p.x(), p.y()));
      }
    }
    return g;
  }

  void add_building(const Rect& lot) {
    const double yaw = rng_.uniform(-0.12, 0.12);
    // Largest rectangle of the lot's aspect that fits after rotating by yaw, minus a margin.
    const double c = std::cos(yaw), s = std::abs(std::sin(yaw));
    const double margin = rng_.uniform(0.5, 2.0);
    const double W = lot.width() - 2 * margin, H = lot.height() - 2 * margin;
    const double w = std::max(4.0, (W * c - H * s) / (c * c - s * s));
    const double h = std::max(4.0, (H * c - W * s) / (c * c - s * s));
    const Eigen::Vector2d centre(0.5 * (lot.x0 + lot.x1), 0.5 * (lot.y0 + lot.y1));
    const Eigen::Vector2d half_local(0.5 * w, 0.5 * h);
    LocalFrame frame;
    frame.yaw = yaw;
    frame.origin = centre - Eigen::Rotation2Dd(yaw) * half_local;

    // Footprint (local, counter-clockwise), optionally with a recess in a long side.
    std::vector<Eigen::Vector2d> fp;
    const bool recess = w > 14.0 && h > 9.0 && rng_.uniform() < 0.5;
    if (recess) {
      const double rw = rng_.uniform(0.25, 0.45) * w, rd = rng_.uniform(1.5, 3.5);
      const double r0 = rng_.uniform(0.2 * w, 0.8 * w - rw);
      const bool front = rng_.uniform() < 0.5;
      if (front) {
        fp = {{0, 0}, {r0, 0}, {r0, rd}, {r0 + rw, rd}, {r0 + rw, 0}, {w, 0}, {w, h}, {0, h}};
      } else {
        fp = {{0, 0}, {w, 0}, {w, h}, {r0 + rw, h}, {r0 + rw, h - rd}, {r0, h - rd}, {r0, h}, {0, h}};
      }
    } else {
      fp = {{0, 0}, {w, 0}, {w, h}, {0, h}};
    }
    const double u = rng_.uniform();
    const RoofType roof = recess ? (u < 0.5 ? RoofType::kFlat : RoofType::kShed)
                                 : (u < 0.34   ? RoofType::kFlat
                                    : u < 0.67 ? RoofType::kShed
                                               : RoofType::kGabled);
    const double pitch =
        roof == RoofType::kFlat ? 0.0 : rng_.uniform(8.0, std::max(8.0, s_.max_roof_pitch_deg)) * kPi / 180;
    std::vector<Eigen::Vector3d> outline;
    for (const auto& p : fp) outline.push_back(frame.to_world(p.x(), p.y(), 0));
    const double base = min_ground(outline) - 0.3;
    const double ground_level = base + 0.3;
    const double eave = ground_level + rng_.uniform(s_.min_building_height, s_.max_building_height);
    // Roof height over local (x, y).
    const double slope = std::tan(pitch);
    const auto roof_z = [&](double, double y) {
      switch (roof) {
        case RoofType::kFlat: return eave;
        case RoofType::kShed: return eave + slope * y;
        case RoofType::kGabled: return eave + slope * std::min(y, h - y);
      }
      return eave;
    };
    // Façades: one vertical polygon per footprint edge (pentagons on the gable ends).
    for (std::size_t i = 0; i < fp.size(); ++i) {
      const Eigen::Vector2d& a = fp[i];
      const Eigen::Vector2d& b = fp[(i + 1) % fp.size()];
      std::vector<Eigen::Vector3d> v = {frame.to_world(a.x(), a.y(), base),
                                        frame.to_world(b.x(), b.y(), base),
                                        frame.to_world(b.x(), b.y(), roof_z(b.x(), b.y()))};
      if (roof == RoofType::kGabled && std::abs(a.x() - b.x()) < 1e-9) {
        v.push_back(frame.to_world(a.x(), 0.5 * h, roof_z(a.x(), 0.5 * h)));  // apex
      }
      v.push_back(frame.to_world(a.x(), a.y(), roof_z(a.x(), a.y())));
      add_surface(std::move(v), ObjectKind::kFacade, true);
      if ((b - a).norm() > 6.0) add_balconies(frame, a, b, ground_level, eave);
    }
    // Roof.
    if (roof == RoofType::kGabled) {
      const double ridge = roof_z(0, 0.5 * h);
      add_surface({frame.to_world(0, 0, eave), frame.to_world(w, 0, eave), frame.to_world(w, 0.5 * h, ridge),
                   frame.to_world(0, 0.5 * h, ridge)},
                  ObjectKind::kRoof, true);
      add_surface({frame.to_world(w, h, eave), frame.to_world(0, h, eave), frame.to_world(0, 0.5 * h, ridge),
                   frame.to_world(w, 0.5 * h, ridge)},
                  ObjectKind::kRoof, true);
    } else {
      std::vector<Eigen::Vector3d> v;
      for (const auto& p : fp) v.push_back(frame.to_world(p.x(), p.y(), roof_z(p.x(), p.y())));
      add_surface(std::move(v), ObjectKind::kRoof, true);
    }
    Footprint f;
    f.kind = ObjectKind::kFacade;
    for (const auto& p : outline) f.outline.push_back(p.head<2>());
    world_.footprints.push_back(std::move(f));
  }

  void add_balconies(const LocalFrame& frame, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                     double ground_level, double eave) {
    const Eigen::Vector2d dir = (b - a).normalized();
    const Eigen::Vector2d out(dir.y(), -dir.x());  // outward for a counter-clockwise footprint
    const double length = (b - a).norm();
    const double edge_yaw = frame.yaw + std::atan2(dir.y(), dir.x());
    for (double z = ground_level + 3.0; z < eave - 1.5; z += 3.0) {
      for (double t = 2.5; t < length - 2.5; t += 4.0) {
        if (rng_.uniform() > 0.2) continue;
        const Eigen::Vector2d p = a + t * dir + 0.6 * out;
        add(OrientedBox{frame.to_world(p.x(), p.y(), z + 0.5), {1.2, 0.6, 0.5}, edge_yaw},
            ObjectKind::kBalcony);
      }
    }
  }

  void add_free_wall(const Rect& lot) {
    const bool along_x = lot.width() >= lot.height();
    const double length = std::min(rng_.uniform(8.0, 20.0), (along_x ? lot.width() : lot.height()) - 2.0);
    const double thick = 0.3, height = rng_.uniform(1.8, 3.5);
    const double yaw = (along_x ? 0.0 : 0.5 * kPi) + rng_.uniform(-0.1, 0.1);
    const double centre_y = rng_.uniform(lot.y0 + 0.4 * lot.height(), lot.y1 - 0.4 * lot.height());
    const double centre_x = rng_.uniform(lot.x0 + 0.4 * lot.width(), lot.x1 - 0.4 * lot.width());
    const Eigen::Vector2d centre(centre_x, centre_y);  // y drawn first, as in reversed_draws
    LocalFrame frame;
    frame.yaw = yaw;
    frame.origin = centre - Eigen::Rotation2Dd(yaw) * Eigen::Vector2d(0.5 * length, 0.5 * thick);
    const std::vector<Eigen::Vector2d> fp = {{0, 0}, {length, 0}, {length, thick}, {0, thick}};
    std::vector<Eigen::Vector3d> outline;
    for (const auto& p : fp) outline.push_back(frame.to_world(p.x(), p.y(), 0));
    const double base = min_ground(outline) - 0.3, top = base + 0.3 + height;
    for (std::size_t i = 0; i < fp.size(); ++i) {
      const Eigen::Vector2d& a = fp[i];
      const Eigen::Vector2d& b = fp[(i + 1) % fp.size()];
      const bool long_side = (b - a).norm() > 1.0;
      add_surface({frame.to_world(a.x(), a.y(), base), frame.to_world(b.x(), b.y(), base),
                   frame.to_world(b.x(), b.y(), top), frame.to_world(a.x(), a.y(), top)},
                  ObjectKind::kWall, long_side);
    }
    std::vector<Eigen::Vector3d> cap;
    for (const auto& p : fp) cap.push_back(frame.to_world(p.x(), p.y(), top));
    add_surface(std::move(cap), ObjectKind::kWall, false);
    Footprint f;
    f.kind = ObjectKind::kWall;
    for (const auto& p : outline) f.outline.push_back(p.head<2>());
    world_.footprints.push_back(std::move(f));
  }

  // ---- primitives ---------------------------------------------------------------------------
  void add(Shape shape, ObjectKind kind, int landmark = -1) {
    world_.primitives.push_back(Primitive{std::move(shape), kind, landmark});
  }

  void add_surface(std::vector<Eigen::Vector3d> vertices, ObjectKind kind, bool landmark) {
    Polygon polygon(std::move(vertices));
    if (polygon.vertices().empty()) return;
    int id = -1;
    if (landmark) {
      Landmark lm;
      lm.id = static_cast<int>(world_.landmarks.size());
      lm.kind = kind;
      lm.normal = polygon.normal();
      lm.d = polygon.d();
      lm.polygon = polygon.vertices();
      lm.area = polygon.area();
      world_.landmarks.push_back(std::move(lm));
      id = world_.landmarks.back().id;
    }
    add(std::move(polygon), kind, id);
  }

  void footprint_box(const Eigen::Vector2d& c, double hx, double hy, double yaw, ObjectKind kind) {
    Footprint f;
    f.kind = kind;
    const Eigen::Rotation2Dd R(yaw);
    for (const auto& corner : {Eigen::Vector2d(-hx, -hy), Eigen::Vector2d(hx, -hy), Eigen::Vector2d(hx, hy),
                               Eigen::Vector2d(-hx, hy)})
      f.outline.push_back(c + R * corner);
    world_.footprints.push_back(std::move(f));
  }

  const WorldSettings& s_;
  double start_clearance_;
  Rng& rng_;
  World world_;
};

}  // namespace

World build_world(const WorldSettings& settings, double start_clearance, Rng& rng) {
  return Builder(settings, start_clearance, rng).build();
}

}  // namespace sextant::synth
