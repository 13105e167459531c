#include "bullet_sim_core/scene_renderer.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <set>
#include <thread>
#include <tuple>

#include "bullet_sim_core/mesh_loader.h"
#include "bullet_sim_core/physics_world.h"

namespace bullet_sim {

constexpr double kPi = 3.14159265358979323846;

// ---------------------------------------------------------------------------------------------
// Geometry: each distinct geometry becomes a triangle list once, in the visual's frame.
// Triangles wind counter-clockwise seen from outside, so (b - a) x (c - a) points outward.
// ---------------------------------------------------------------------------------------------
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;

struct Mesh {
  struct Triangle {
    std::array<int, 3> v;
    std::array<Vector2d, 3> uv;  // texture coordinates: s right, t down, both in [0, 1]
  };
  std::vector<Vector3d> vertices;
  std::vector<Triangle> triangles;
  bool single_sided = true;  // closed and consistently wound: back faces can be culled
  bool has_uv = false;
  Vector3d centre = Vector3d::Zero();  // bounding sphere, for frustum culling
  double radius = 0;

  // A quad given bottom-left, bottom-right, top-right, top-left as seen from its front; the
  // whole texture spans it upright.
  void quad(const Vector3d& bl, const Vector3d& br, const Vector3d& tr, const Vector3d& tl) {
    const int i = static_cast<int>(vertices.size());
    vertices.insert(vertices.end(), {bl, br, tr, tl});
    const Vector2d uv_bl(0, 1), uv_br(1, 1), uv_tr(1, 0), uv_tl(0, 0);
    triangles.push_back({{i, i + 1, i + 2}, {uv_bl, uv_br, uv_tr}});
    triangles.push_back({{i, i + 2, i + 3}, {uv_bl, uv_tr, uv_tl}});
  }
  void finish() {
    if (vertices.empty()) return;
    Vector3d lo = vertices[0], hi = vertices[0];
    for (const Vector3d& v : vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
    centre = (lo + hi) / 2;
    for (const Vector3d& v : vertices) radius = std::max(radius, (v - centre).norm());
  }
};

Mesh boxMesh(const Vector3d& size) {
  Mesh m;
  m.has_uv = true;
  const Vector3d h = size / 2;
  // Outward normal and the image's "up" on that face. right = up x normal keeps the image
  // unmirrored for a viewer outside (right x up = normal).
  const std::array<std::pair<Vector3d, Vector3d>, 6> faces = {{{Vector3d::UnitX(), Vector3d::UnitZ()},
                                                               {-Vector3d::UnitX(), Vector3d::UnitZ()},
                                                               {Vector3d::UnitY(), Vector3d::UnitZ()},
                                                               {-Vector3d::UnitY(), Vector3d::UnitZ()},
                                                               {Vector3d::UnitZ(), Vector3d::UnitX()},
                                                               {-Vector3d::UnitZ(), Vector3d::UnitX()}}};
  for (const auto& [n, up] : faces) {
    const Vector3d right = up.cross(n);
    const Vector3d c = n * n.cwiseAbs().dot(h), r = right * right.cwiseAbs().dot(h), u = up * up.cwiseAbs().dot(h);
    m.quad(c - r - u, c + r - u, c + r + u, c - r + u);
  }
  m.finish();
  return m;
}

// Along local z, `segments` facets around.
Mesh cylinderMesh(double radius, double length, int segments) {
  Mesh m;
  const double h = length / 2;
  for (int i = 0; i < segments; ++i) {
    const double a = 2 * kPi * i / segments;
    m.vertices.emplace_back(radius * std::cos(a), radius * std::sin(a), -h);
    m.vertices.emplace_back(radius * std::cos(a), radius * std::sin(a), h);
  }
  const int bottom = static_cast<int>(m.vertices.size()), top = bottom + 1;
  m.vertices.emplace_back(0, 0, -h);
  m.vertices.emplace_back(0, 0, h);
  const Vector2d o(0, 0);
  for (int i = 0; i < segments; ++i) {
    const int p0 = 2 * i, q0 = p0 + 1, p1 = 2 * ((i + 1) % segments), q1 = p1 + 1;
    m.triangles.push_back({{p0, p1, q1}, {o, o, o}});
    m.triangles.push_back({{p0, q1, q0}, {o, o, o}});
    m.triangles.push_back({{top, q0, q1}, {o, o, o}});
    m.triangles.push_back({{bottom, p1, p0}, {o, o, o}});
  }
  m.finish();
  return m;
}

Mesh sphereMesh(double radius, int segments) {
  Mesh m;
  const int stacks = std::max(2, segments / 2);
  for (int k = 0; k <= stacks; ++k) {
    const double lat = -kPi / 2 + kPi * k / stacks;
    for (int i = 0; i < segments; ++i) {
      const double lon = 2 * kPi * i / segments;
      m.vertices.emplace_back(radius * std::cos(lat) * std::cos(lon), radius * std::cos(lat) * std::sin(lon),
                              radius * std::sin(lat));
    }
  }
  const Vector2d o(0, 0);
  for (int k = 0; k < stacks; ++k)
    for (int i = 0; i < segments; ++i) {
      const int a = k * segments + i, b = k * segments + (i + 1) % segments, c = b + segments, d = a + segments;
      if (k > 0) m.triangles.push_back({{a, b, c}, {o, o, o}});           // the bottom row's is degenerate
      if (k < stacks - 1) m.triangles.push_back({{a, c, d}, {o, o, o}});  // and so is the top row's
    }
  m.finish();
  return m;
}

// Gazebo draws a plane as a finite quad of <size>, its x along the frame's x rotated onto the normal.
Mesh planeMesh(const Vector3d& normal, const Vector2d& size) {
  Mesh m;
  m.has_uv = true;
  const Eigen::Matrix3d rot = Eigen::Quaterniond::FromTwoVectors(Vector3d::UnitZ(), normal.normalized()).toRotationMatrix();
  const Vector3d x = rot.col(0) * size.x() / 2, y = rot.col(1) * size.y() / 2;
  m.quad(-x - y, x - y, x + y, -x + y);
  m.finish();
  return m;
}

Mesh fileMesh(const std::string& path, const Vector3d& scale) {
  const TriangleMesh& source = loadMesh(path);  // throws DescriptionError
  Mesh m;
  m.single_sided = false;  // files do not promise consistent winding or closed surfaces
  for (const Vector3d& v : source.vertices) m.vertices.push_back(v.cwiseProduct(scale));
  const Vector2d o(0, 0);
  for (const auto& t : source.triangles) m.triangles.push_back({t, {o, o, o}});
  m.finish();
  return m;
}

// What identifies a triangulation: the type and the numbers that shape it.
struct GeometryKey {
  int type;
  std::array<double, 5> v{};
  std::string file;
  bool operator<(const GeometryKey& o) const { return std::tie(type, v, file) < std::tie(o.type, o.v, o.file); }
};

GeometryKey keyOf(const Geometry& g) {
  GeometryKey k{static_cast<int>(g.type), {}, {}};
  switch (g.type) {
    case GeometryType::Box: k.v = {g.box_size.x(), g.box_size.y(), g.box_size.z(), 0, 0}; break;
    case GeometryType::Cylinder: k.v = {g.radius, g.length, 0, 0, 0}; break;
    case GeometryType::Sphere: k.v = {g.radius, 0, 0, 0, 0}; break;
    case GeometryType::Plane:
      k.v = {g.plane_normal.x(), g.plane_normal.y(), g.plane_normal.z(), g.plane_size.x(), g.plane_size.y()};
      break;
    case GeometryType::Mesh:
      k.v = {g.mesh_scale.x(), g.mesh_scale.y(), g.mesh_scale.z(), 0, 0};
      k.file = g.mesh_file;
      break;
  }
  return k;
}

// An RGB image and its successive halvings (a mip chain), so that a texture seen small is
// sampled from a level with about one texel per pixel instead of aliasing.
struct Texture {
  struct Level {
    int width, height;
    std::vector<std::uint8_t> rgb;
  };
  std::vector<Level> levels;
};

std::unique_ptr<Texture> loadTexture(const std::string& path) {
  const cv::Mat bgr = cv::imread(path, cv::IMREAD_COLOR);
  if (bgr.empty()) return nullptr;
  auto t = std::make_unique<Texture>();
  Texture::Level level{bgr.cols, bgr.rows, std::vector<std::uint8_t>(static_cast<size_t>(bgr.cols) * bgr.rows * 3)};
  for (int y = 0; y < bgr.rows; ++y)
    for (int x = 0; x < bgr.cols; ++x) {
      const cv::Vec3b p = bgr.at<cv::Vec3b>(y, x);
      std::uint8_t* q = &level.rgb[(static_cast<size_t>(y) * bgr.cols + x) * 3];
      q[0] = p[2], q[1] = p[1], q[2] = p[0];
    }
  t->levels.push_back(std::move(level));
  while (t->levels.back().width > 1 || t->levels.back().height > 1) {
    const Texture::Level& a = t->levels.back();
    Texture::Level b{std::max(1, a.width / 2), std::max(1, a.height / 2), {}};
    b.rgb.resize(static_cast<size_t>(b.width) * b.height * 3);
    for (int y = 0; y < b.height; ++y)
      for (int x = 0; x < b.width; ++x)
        for (int ch = 0; ch < 3; ++ch) {
          int sum = 0;
          for (int dy = 0; dy < 2; ++dy)
            for (int dx = 0; dx < 2; ++dx) {
              const int sx = std::min(2 * x + dx, a.width - 1), sy = std::min(2 * y + dy, a.height - 1);
              sum += a.rgb[(static_cast<size_t>(sy) * a.width + sx) * 3 + ch];
            }
          b.rgb[(static_cast<size_t>(y) * b.width + x) * 3 + ch] = static_cast<std::uint8_t>((sum + 2) / 4);
        }
    t->levels.push_back(std::move(b));
  }
  return t;
}

// ---------------------------------------------------------------------------------------------
// Rasterization. Screen coordinates are continuous: pixel (i, j) covers [i, i+1) x [j, j+1) and
// is sampled at its centre; the optical axis hits the image centre (W/2, H/2).
// ---------------------------------------------------------------------------------------------

// A camera-space vertex: optical frame (x right, y down, z forward) and texture coordinates.
struct ClipVertex {
  Vector3d p;
  Vector2d uv;
};

// A triangle ready to fill. Everything that is affine in screen space: the three edge functions
// (>= 0 inside), w = 1/z (perspective-correct depth), and s*w, t*w (perspective-correct texture).
struct ScreenTriangle {
  double ea[3], eb[3], ec[3];
  double wa, wb, wc;
  double sa, sb, sc, ta, tb, tc;
  int x0, x1, y0, y1;  // bounding box, clamped to the image
  std::uint8_t rgb[3];             // flat colour, already in the output's channel order
  const Texture::Level* texture;  // when set, texture colour * shade replaces rgb
  float shade;
};

// The coefficients (a, b, c) of the affine function a x + b y + c that takes values f0, f1, f2
// at the vertices (area2: twice the signed area of the screen triangle).
void affine(const double u[3], const double v[3], double area2, double f0, double f1, double f2, double& a, double& b,
            double& c) {
  a = ((f1 - f0) * (v[2] - v[0]) - (f2 - f0) * (v[1] - v[0])) / area2;
  b = ((f2 - f0) * (u[1] - u[0]) - (f1 - f0) * (u[2] - u[0])) / area2;
  c = f0 - a * u[0] - b * v[0];
}

// Writes the texel colour at (s, t), times shade, to out[r], out[1], out[2 - r] (r = 2 for bgr8).
inline void sampleBilinear(const Texture::Level& t, double s, double tt, float shade, int r, std::uint8_t* out) {
  const float x = std::clamp(static_cast<float>(s * t.width - 0.5), 0.0f, static_cast<float>(t.width - 1));
  const float y = std::clamp(static_cast<float>(tt * t.height - 0.5), 0.0f, static_cast<float>(t.height - 1));
  const int x0 = static_cast<int>(x), y0 = static_cast<int>(y);
  const int x1 = std::min(x0 + 1, t.width - 1), y1 = std::min(y0 + 1, t.height - 1);
  const float fx = x - x0, fy = y - y0;
  const std::uint8_t* p00 = &t.rgb[(static_cast<size_t>(y0) * t.width + x0) * 3];
  const std::uint8_t* p10 = &t.rgb[(static_cast<size_t>(y0) * t.width + x1) * 3];
  const std::uint8_t* p01 = &t.rgb[(static_cast<size_t>(y1) * t.width + x0) * 3];
  const std::uint8_t* p11 = &t.rgb[(static_cast<size_t>(y1) * t.width + x1) * 3];
  for (int ch = 0; ch < 3; ++ch) {
    const float top = p00[ch] + fx * (p10[ch] - p00[ch]), bottom = p01[ch] + fx * (p11[ch] - p01[ch]);
    out[ch == 1 ? 1 : ch == 0 ? r : 2 - r] =
        static_cast<std::uint8_t>(std::min(255.0f, (top + fy * (bottom - top)) * shade + 0.5f));
  }
}

// Fills the rows [row_begin, row_end) of one triangle; r is where red goes (0, or 2 for bgr8).
void fill(const ScreenTriangle& t, int row_begin, int row_end, int width, int r, float* depth, std::uint8_t* rgb) {
  const int y_end = std::min(t.y1 + 1, row_end);
  for (int y = std::max(t.y0, row_begin); y < y_end; ++y) {
    const double yc = y + 0.5;
    // The span of x where all three edge functions are >= 0.
    double left = t.x0 - 1.0, right = t.x1 + 1.0;
    bool empty = false;
    for (int k = 0; k < 3; ++k) {
      const double a = t.ea[k], r = t.eb[k] * yc + t.ec[k];
      if (a > 0) left = std::max(left, -r / a);
      else if (a < 0) right = std::min(right, -r / a);
      else empty = empty || r < 0;
    }
    if (empty || left > right) continue;
    const int i0 = std::max(t.x0, static_cast<int>(std::ceil(left - 0.5)));
    const int i1 = std::min(t.x1, static_cast<int>(std::floor(right - 0.5)));
    const double w_row = t.wb * yc + t.wc;
    float* d = depth + static_cast<size_t>(y) * width;
    std::uint8_t* c = rgb + static_cast<size_t>(y) * width * 3;
    if (!t.texture) {
      for (int i = i0; i <= i1; ++i) {
        const float w = static_cast<float>(t.wa * (i + 0.5) + w_row);
        if (w <= d[i]) continue;
        d[i] = w;
        c[3 * i] = t.rgb[0], c[3 * i + 1] = t.rgb[1], c[3 * i + 2] = t.rgb[2];
      }
    } else {
      const double s_row = t.sb * yc + t.sc, t_row = t.tb * yc + t.tc;
      for (int i = i0; i <= i1; ++i) {
        const double xc = i + 0.5, w = t.wa * xc + w_row;
        if (static_cast<float>(w) <= d[i]) continue;
        d[i] = static_cast<float>(w);
        sampleBilinear(*t.texture, (t.sa * xc + s_row) / w, (t.ta * xc + t_row) / w, t.shade, r, c + 3 * i);
      }
    }
  }
}

}  // namespace

struct SceneRenderer::Impl {
  std::map<GeometryKey, std::unique_ptr<Mesh>> meshes;         // nullptr: could not be made
  std::map<std::string, std::unique_ptr<Texture>> textures;    // nullptr: could not be read
  std::vector<std::string> warnings;
  std::vector<ScreenTriangle> triangles;  // this frame's, reused
  std::vector<Vector3d> camera_vertices;  // scratch
  std::vector<float> depth;               // w = 1/z per pixel; larger is nearer

  // Per frame.
  int width = 0, height = 0;
  int red = 0;  // channel red is written to: 0 for rgb8, 2 for bgr8
  double f = 0, cx = 0, cy = 0, near = 0, far = 0;
  Vector3d to_sun;  // optical frame
  Eigen::Isometry3d optical_from_world;
  std::array<Eigen::Vector3d, 4> side_normals;  // frustum sides, pointing out

  const Mesh* mesh(const Geometry& g, int segments) {
    const GeometryKey key = keyOf(g);
    auto it = meshes.find(key);
    if (it != meshes.end()) return it->second.get();
    std::unique_ptr<Mesh> m;
    switch (g.type) {
      case GeometryType::Box: m = std::make_unique<Mesh>(boxMesh(g.box_size)); break;
      case GeometryType::Cylinder: m = std::make_unique<Mesh>(cylinderMesh(g.radius, g.length, segments)); break;
      case GeometryType::Sphere: m = std::make_unique<Mesh>(sphereMesh(g.radius, segments)); break;
      case GeometryType::Plane: m = std::make_unique<Mesh>(planeMesh(g.plane_normal, g.plane_size)); break;
      case GeometryType::Mesh:
        try {
          m = std::make_unique<Mesh>(fileMesh(g.mesh_file, g.mesh_scale));
        } catch (const std::exception& e) {
          warnings.push_back(std::string("camera: not drawing a mesh visual: ") + e.what());
        }
        break;
    }
    return meshes.emplace(key, std::move(m)).first->second.get();
  }

  const Texture* texture(const std::string& path) {
    auto it = textures.find(path);
    if (it != textures.end()) return it->second.get();
    std::unique_ptr<Texture> t = loadTexture(path);
    if (!t) warnings.push_back("camera: cannot read texture " + path + "; the visual keeps its colour");
    return textures.emplace(path, std::move(t)).first->second.get();
  }

  void beginFrame(const Eigen::Isometry3d& camera_in_world, const CameraConfig& config, const RenderSettings& s) {
    width = config.width, height = config.height;
    red = config.encoding == "bgr8" ? 2 : 0;
    f = width / (2.0 * std::tan(config.horizontal_fov / 2.0));
    cx = width / 2.0, cy = height / 2.0;
    near = config.near_clip, far = config.far_clip;
    // Gazebo's sensor frame (x forward, z up) to the optical frame (z forward, x right, y down).
    Eigen::Matrix3d optical_from_sensor;
    optical_from_sensor << 0, -1, 0, 0, 0, -1, 1, 0, 0;
    optical_from_world = Eigen::Isometry3d(optical_from_sensor) * camera_in_world.inverse();
    to_sun = (optical_from_world.linear() * -s.sun_direction).normalized();
    const double tx = cx / f, ty = cy / f;  // half-extents of the image plane at z = 1
    side_normals = {Vector3d(1, 0, -tx).normalized(), Vector3d(-1, 0, -tx).normalized(),
                    Vector3d(0, 1, -ty).normalized(), Vector3d(0, -1, -ty).normalized()};
    triangles.clear();
  }

  void addVisual(const VisualShape& visual, const Eigen::Isometry3d& pose, const RenderSettings& s) {
    if (visual.rgba[3] <= 0) return;
    const Mesh* m = mesh(visual.geometry, s.segments);
    if (!m || m->triangles.empty()) return;
    const Eigen::Isometry3d to_camera = optical_from_world * pose;
    // Whole visual outside the view frustum (near, far, four sides)?
    const Vector3d c = to_camera * m->centre;
    if (c.z() + m->radius < near || c.z() - m->radius > far) return;
    for (const Vector3d& n : side_normals)
      if (n.dot(c) > m->radius) return;
    const Texture* tex = m->has_uv && !visual.texture_file.empty() ? texture(visual.texture_file) : nullptr;

    camera_vertices.resize(m->vertices.size());
    for (size_t i = 0; i < m->vertices.size(); ++i) camera_vertices[i] = to_camera * m->vertices[i];
    for (const Mesh::Triangle& tri : m->triangles) {
      const Vector3d& a = camera_vertices[tri.v[0]];
      const Vector3d& b = camera_vertices[tri.v[1]];
      const Vector3d& d = camera_vertices[tri.v[2]];
      Vector3d n = (b - a).cross(d - a);
      const double length = n.norm();
      if (length == 0) continue;
      if (n.dot(a) >= 0) {  // facing away from the camera (which is at the origin)
        if (m->single_sided) continue;
        n = -n;
      }
      const float shade = s.ambient + s.sun_diffuse * static_cast<float>(std::max(0.0, n.dot(to_sun) / length));
      const ClipVertex v[3] = {{a, tri.uv[0]}, {b, tri.uv[1]}, {d, tri.uv[2]}};
      clipAndAdd(v, visual.rgba, tex, shade);
    }
  }

  // Sutherland-Hodgman against the near plane (z >= near): 3 vertices in, 0, 3 or 4 out.
  void clipAndAdd(const ClipVertex (&in)[3], const std::array<float, 4>& rgba, const Texture* tex, float shade) {
    if (in[0].p.z() > far && in[1].p.z() > far && in[2].p.z() > far) return;
    ClipVertex out[4];
    int count = 0;
    for (int k = 0; k < 3; ++k) {
      const ClipVertex& cur = in[k];
      const ClipVertex& next = in[(k + 1) % 3];
      const bool cur_in = cur.p.z() >= near, next_in = next.p.z() >= near;
      if (cur_in) out[count++] = cur;
      if (cur_in != next_in) {
        const double t = (near - cur.p.z()) / (next.p.z() - cur.p.z());
        out[count] = {cur.p + t * (next.p - cur.p), cur.uv + t * (next.uv - cur.uv)};
        out[count++].p.z() = near;
      }
    }
    for (int k = 1; k + 1 < count; ++k) addScreenTriangle(out[0], out[k], out[k + 1], rgba, tex, shade);
  }

  void addScreenTriangle(const ClipVertex& v0, const ClipVertex& v1, const ClipVertex& v2,
                         const std::array<float, 4>& rgba, const Texture* tex, float shade) {
    const ClipVertex* v[3] = {&v0, &v1, &v2};
    double u[3], y[3], w[3];
    for (int k = 0; k < 3; ++k) {
      w[k] = 1.0 / v[k]->p.z();
      u[k] = cx + f * v[k]->p.x() * w[k];
      y[k] = cy + f * v[k]->p.y() * w[k];
    }
    const double area2 = (u[1] - u[0]) * (y[2] - y[0]) - (u[2] - u[0]) * (y[1] - y[0]);
    if (!(std::abs(area2) > 1e-9)) return;  // degenerate (or NaN)
    const double x_lo = std::min({u[0], u[1], u[2]}), x_hi = std::max({u[0], u[1], u[2]});
    const double y_lo = std::min({y[0], y[1], y[2]}), y_hi = std::max({y[0], y[1], y[2]});
    if (x_hi < 0 || y_hi < 0 || x_lo > width || y_lo > height) return;
    ScreenTriangle t;
    t.x0 = static_cast<int>(std::max(0.0, std::floor(x_lo)));
    t.x1 = static_cast<int>(std::min(width - 1.0, std::ceil(x_hi)));
    t.y0 = static_cast<int>(std::max(0.0, std::floor(y_lo)));
    t.y1 = static_cast<int>(std::min(height - 1.0, std::ceil(y_hi)));
    for (int k = 0; k < 3; ++k) {
      const int i = k, j = (k + 1) % 3, o = (k + 2) % 3;
      double a = y[i] - y[j], b = u[j] - u[i], c = u[i] * y[j] - u[j] * y[i];
      if (a * u[o] + b * y[o] + c < 0) a = -a, b = -b, c = -c;  // inside is where the third vertex is
      t.ea[k] = a, t.eb[k] = b, t.ec[k] = c;
    }
    affine(u, y, area2, w[0], w[1], w[2], t.wa, t.wb, t.wc);
    t.texture = nullptr;
    t.shade = shade;
    for (int ch = 0; ch < 3; ++ch)
      t.rgb[ch == 1 ? 1 : ch == 0 ? red : 2 - red] =
          static_cast<std::uint8_t>(std::lround(std::clamp(rgba[ch] * shade, 0.0f, 1.0f) * 255));
    if (tex) {
      const Vector2d& a = v0.uv;
      const Vector2d& b = v1.uv;
      const Vector2d& c = v2.uv;
      affine(u, y, area2, a.x() * w[0], b.x() * w[1], c.x() * w[2], t.sa, t.sb, t.sc);
      affine(u, y, area2, a.y() * w[0], b.y() * w[1], c.y() * w[2], t.ta, t.tb, t.tc);
      // Mip level: about one texel per pixel over this triangle.
      const Texture::Level& base = tex->levels.front();
      const double uv_area = std::abs((b - a).x() * (c - a).y() - (c - a).x() * (b - a).y()) / 2;
      const double texels_per_pixel = uv_area * base.width * base.height / (std::abs(area2) / 2);
      const int level = texels_per_pixel > 1 ? static_cast<int>(0.5 * std::log2(texels_per_pixel)) : 0;
      t.texture = &tex->levels[std::min<size_t>(level, tex->levels.size() - 1)];
    }
    triangles.push_back(t);
  }

  void rasterize(const RenderSettings& s, CameraImage& out) {
    out.width = width, out.height = height;
    out.encoding = red ? "bgr8" : "rgb8";
    const size_t row_bytes = static_cast<size_t>(width) * 3;
    out.data.resize(row_bytes * height);
    std::uint8_t bg[3];
    for (int ch = 0; ch < 3; ++ch)
      bg[ch == 1 ? 1 : ch == 0 ? red : 2 - red] =
          static_cast<std::uint8_t>(std::lround(std::clamp(s.background[ch], 0.0f, 1.0f) * 255));
    for (int x = 0; x < width; ++x) std::copy(bg, bg + 3, &out.data[3 * x]);
    for (int y = 1; y < height; ++y) std::copy_n(out.data.begin(), row_bytes, out.data.begin() + y * row_bytes);
    // Anything beyond the far plane has w < 1/far and fails the depth test.
    depth.assign(static_cast<size_t>(width) * height, static_cast<float>(1.0 / far));

    const int bands = std::clamp(s.threads, 1, height);
    auto band = [&](int b) {
      const int y0 = height * b / bands, y1 = height * (b + 1) / bands;
      for (const ScreenTriangle& t : triangles)
        if (t.y1 >= y0 && t.y0 < y1) fill(t, y0, y1, width, red, depth.data(), out.data.data());
    };
    std::vector<std::thread> workers;
    for (int b = 1; b < bands; ++b) workers.emplace_back(band, b);
    band(0);
    for (std::thread& w : workers) w.join();
  }
};

SceneRenderer::SceneRenderer(RenderSettings settings)
    : settings_(std::move(settings)), impl_(std::make_unique<Impl>()) {
  settings_.segments = std::max(3, settings_.segments);
}

SceneRenderer::~SceneRenderer() = default;

std::vector<SceneItem> SceneRenderer::collect(const PhysicsWorld& world) {
  std::vector<SceneItem> items;
  for (const std::string& name : world.modelNames()) {
    const PhysicsModel* model = world.findModel(name);
    if (!model) continue;
    for (const LinkDescription& link : model->description().links) {
      if (link.visuals.empty() || !model->hasLink(link.name)) continue;
      const Eigen::Isometry3d pose = model->linkPose(link.name);
      for (const VisualShape& v : link.visuals) items.push_back({&v, pose * v.origin});
    }
  }
  return items;
}

void SceneRenderer::render(const PhysicsWorld& world, const Eigen::Isometry3d& camera_in_world,
                           const CameraConfig& config, CameraImage& out) {
  render(collect(world), camera_in_world, config, out);
}

void SceneRenderer::render(const std::vector<SceneItem>& items, const Eigen::Isometry3d& camera_in_world,
                           const CameraConfig& config, CameraImage& out) {
  impl_->beginFrame(camera_in_world, config, settings_);
  for (const SceneItem& item : items)
    if (item.visual) impl_->addVisual(*item.visual, item.pose, settings_);
  impl_->rasterize(settings_, out);
}

std::vector<std::string> SceneRenderer::takeWarnings() {
  std::vector<std::string> w;
  w.swap(impl_->warnings);
  return w;
}

void encodeImage(const CameraImage& image, const std::string& encoding, std::vector<std::uint8_t>& out) {
  const size_t pixels = static_cast<size_t>(image.width) * image.height;
  const std::uint8_t* __restrict in = image.data.data();
  const int r = image.encoding == "bgr8" ? 2 : 0, b = 2 - r;  // where red and blue are in `image`
  if (encoding == "mono8") {
    out.resize(pixels);
    std::uint8_t* __restrict o = out.data();
    for (size_t i = 0; i < pixels; ++i)
      o[i] = static_cast<std::uint8_t>((77 * in[3 * i + r] + 150 * in[3 * i + 1] + 29 * in[3 * i + b] + 128) >> 8);
  } else if (encoding == image.encoding) {
    out.assign(image.data.begin(), image.data.end());
  } else {  // rgb8 <-> bgr8
    out.resize(pixels * 3);
    std::uint8_t* __restrict o = out.data();
    for (size_t i = 0; i < 3 * pixels; i += 3) o[i] = in[i + 2], o[i + 1] = in[i + 1], o[i + 2] = in[i];
  }
}

}  // namespace bullet_sim
