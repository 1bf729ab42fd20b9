#include "render.h"
#include "motion_box.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace deformseg::tool {

View view_of(const mesh::Surface_mesh_animation& animation) {
  const Motion_box box = motion_box(animation);
  View view;
  view.low = box.low, view.high = box.high;
  Eigen::Index thinnest = 0;
  (view.high - view.low).minCoeff(&thinnest);
  view.toward_viewer = Eigen::Vector3d::Unit(thinnest);
  view.up = thinnest == 1 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitY();
  view.right = view.up.cross(view.toward_viewer);
  return view;
}

namespace {

// Twice the signed area of the triangle (a, b, p): which side of a -> b the point p is on.
double edge(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p) {
  return (b.x() - a.x()) * (p.y() - a.y()) - (b.y() - a.y()) * (p.x() - a.x());
}

color::Rgb shaded(color::Rgb color, double light) {
  const auto scale = [light](std::uint8_t c) { return std::uint8_t(std::lround(double(c) * light)); };
  return {scale(color.r), scale(color.g), scale(color.b)};
}

}  // namespace

Image render_frame(const mesh::Surface_mesh_animation& animation, std::size_t t, const View& view,
                   std::span<const color::Rgb> colors, int size) {
  // The box's corners projected: the picture's extent, the same for every frame.
  const Eigen::Vector3d extent = view.high - view.low;
  const double width = std::abs(extent.dot(view.right)), height = std::abs(extent.dot(view.up));
  const double scale = double(size - 1) / std::max({width, height, std::numeric_limits<double>::min()});
  Image image(std::max(1, int(std::ceil(width * scale)) + 1), std::max(1, int(std::ceil(height * scale)) + 1));
  const Eigen::Vector3d centre = (view.low + view.high) / 2;
  const auto frame = animation.frame_matrix(t);
  std::vector<Eigen::Vector2d> screen(animation.num_vertices());
  for (std::size_t v = 0; v < screen.size(); ++v) {
    const Eigen::Vector3d p = frame.col(Eigen::Index(v)) - centre;
    screen[v] = {image.width / 2.0 + p.dot(view.right) * scale, image.height / 2.0 - p.dot(view.up) * scale};
  }
  std::vector<double> depth(std::size_t(image.width) * std::size_t(image.height),
                            -std::numeric_limits<double>::infinity());
  const auto& triangles = animation.triangles();
  for (std::size_t j = 0; j < triangles.size(); ++j) {
    const auto [i0, i1, i2] = triangles[j];
    const Eigen::Vector3d p0 = frame.col(i0), p1 = frame.col(i1), p2 = frame.col(i2);
    const Eigen::Vector3d normal = (p1 - p0).cross(p2 - p0);
    const double area = edge(screen[i0], screen[i1], screen[i2]);
    if (normal.norm() == 0 || area == 0) continue;  // degenerate, or seen edge-on
    const color::Rgb color = shaded(colors[j], 0.35 + 0.65 * std::abs(normal.normalized().dot(view.toward_viewer)));
    const double d0 = p0.dot(view.toward_viewer), d1 = p1.dot(view.toward_viewer), d2 = p2.dot(view.toward_viewer);
    const int x0 = std::max(0, int(std::floor(std::min({screen[i0].x(), screen[i1].x(), screen[i2].x()}))));
    const int x1 =
        std::min(image.width - 1, int(std::ceil(std::max({screen[i0].x(), screen[i1].x(), screen[i2].x()}))));
    const int y0 = std::max(0, int(std::floor(std::min({screen[i0].y(), screen[i1].y(), screen[i2].y()}))));
    const int y1 =
        std::min(image.height - 1, int(std::ceil(std::max({screen[i0].y(), screen[i1].y(), screen[i2].y()}))));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const Eigen::Vector2d pixel(x + 0.5, y + 0.5);
        // Barycentric weights, all of one sign inside whichever way the triangle winds on screen.
        const double w0 = edge(screen[i1], screen[i2], pixel) / area, w1 = edge(screen[i2], screen[i0], pixel) / area;
        const double w2 = 1 - w0 - w1;
        if (w0 < 0 || w1 < 0 || w2 < 0) continue;
        const double d = w0 * d0 + w1 * d1 + w2 * d2;
        double& nearest = depth[std::size_t(y) * std::size_t(image.width) + std::size_t(x)];
        if (d <= nearest) continue;
        nearest = d;
        image.set(x, y, color);
      }
  }
  return image;
}

}  // namespace deformseg::tool
