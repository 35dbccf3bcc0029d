// Sphere covers (amp/world/arm_spheres.hpp) checked independently of how they are made: every mesh
// triangle of the Panda (and a box, a cylinder and a sphere of a small hand-made arm) lies inside the
// spheres of its link, every sphere touches its link's solids, VAMP's spherized Panda is shown not to
// cover until inflated, bad files and sets are refused, and the disk cache reads back what it wrote.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "amp/core/error.hpp"
#include "amp/world/arm_model.hpp"
#include "amp/world/arm_spheres.hpp"
#include "support/sanitizer_build.hpp"
#include "support/sphere_test_cache.hpp"
#include "support/source_tree.hpp"

namespace amp::world {
namespace {

namespace fs = std::filesystem;
using Vec = Eigen::Vector3d;

constexpr int kMaxDepth = 14;  // triangle splits before a piece counts as uncovered

fs::path panda_dir() { return fs::path(AMP_SOURCE_DIR) / ".." / "shared" / "mbm" / "panda"; }

std::vector<LinkSphere> of_link(const std::vector<LinkSphere>& all, int link) {
  std::vector<LinkSphere> out;
  std::copy_if(all.begin(), all.end(), std::back_inserter(out), [link](const LinkSphere& s) { return s.link == link; });
  return out;
}

bool inside(const Vec& p, const LinkSphere& s) { return (p - s.center).norm() <= s.radius; }
bool in_any(const Vec& p, const std::vector<LinkSphere>& spheres) {
  return std::any_of(spheres.begin(), spheres.end(), [&](const LinkSphere& s) { return inside(p, s); });
}

// Covered when one sphere holds all three corners (a ball is convex), else each midpoint quarter is.
bool triangle_covered(const Vec& a, const Vec& b, const Vec& c, const std::vector<LinkSphere>& spheres, int depth) {
  for (const LinkSphere& s : spheres) {
    if (inside(a, s) && inside(b, s) && inside(c, s)) return true;
  }
  if (depth == kMaxDepth || !in_any(a, spheres) || !in_any(b, spheres) || !in_any(c, spheres)) return false;
  const Vec ab = (a + b) / 2, bc = (b + c) / 2, ca = (c + a) / 2;
  return triangle_covered(a, ab, ca, spheres, depth + 1) && triangle_covered(ab, b, bc, spheres, depth + 1) &&
         triangle_covered(ca, bc, c, spheres, depth + 1) && triangle_covered(ab, bc, ca, spheres, depth + 1);
}

std::vector<Vec> posed_vertices(const Solid& s) {
  std::vector<Vec> v;
  for (const Vec& p : s.mesh->vertices) v.push_back(s.pose * p);
  return v;
}

// Points of a box or cylinder: a grid through the volume (faces and rim included) whose spacing
// divides no piece size used here, so its points fall anywhere in the pieces.
std::vector<Vec> volume_points(const Solid& s) {
  constexpr int kSteps = 23;
  std::vector<Vec> out;
  for (int i = 0; i <= kSteps; ++i) {
    for (int j = 0; j <= kSteps; ++j) {
      for (int k = 0; k <= kSteps; ++k) {
        const double u = static_cast<double>(i) / kSteps, v = static_cast<double>(j) / kSteps, w = static_cast<double>(k) / kSteps - 0.5;
        if (s.kind == Solid::Kind::kBox) {
          out.push_back(s.pose * Vec(u - 0.5, v - 0.5, w).cwiseProduct(s.size));
        } else {  // radius fraction u, angle v, height w
          const double a = 2 * std::numbers::pi * v;
          out.push_back(s.pose * Vec(s.radius * u * std::cos(a), s.radius * u * std::sin(a), s.length * w));
        }
      }
    }
  }
  return out;
}

// The whole cover proof for one link's solids; returns the number of failures.
int uncovered(const std::vector<Solid>& solids, const std::vector<LinkSphere>& spheres) {
  int failures = 0;
  for (const Solid& s : solids) {
    if (s.kind == Solid::Kind::kMesh) {
      const std::vector<Vec> v = posed_vertices(s);
      for (const Vec& p : v) failures += in_any(p, spheres) ? 0 : 1;
      for (const Eigen::Vector3i& t : s.mesh->triangles) failures += triangle_covered(v[t[0]], v[t[1]], v[t[2]], spheres, 0) ? 0 : 1;
    } else if (s.kind == Solid::Kind::kSphere) {
      const bool held = std::any_of(spheres.begin(), spheres.end(), [&](const LinkSphere& x) {
        return (x.center - s.pose.translation()).norm() + s.radius <= x.radius;
      });
      failures += held ? 0 : 1;
    } else {
      for (const Vec& p : volume_points(s)) failures += in_any(p, spheres) ? 0 : 1;
    }
  }
  return failures;
}

void expect_cover(const ArmModel& model, const std::vector<LinkSphere>& spheres) {
  for (int l = 0; l < static_cast<int>(model.links().size()); ++l) {
    EXPECT_EQ(uncovered(model.link(l).collision, of_link(spheres, l)), 0) << model.link(l).name;
  }
}

// Nearest point of triangle abc to p (Ericson, Real-Time Collision Detection, 5.1.5).
Vec closest_on_triangle(const Vec& p, const Vec& a, const Vec& b, const Vec& c) {
  const Vec ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const Vec cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double denom = 1 / (va + vb + vc);
  return a + ab * vb * denom + ac * vc * denom;
}

// Distance from p to the link's solids (meshes as surfaces; boxes, cylinders and spheres solid).
double distance_to_solids(const Vec& p, const std::vector<Solid>& solids) {
  double d = std::numeric_limits<double>::infinity();
  for (const Solid& s : solids) {
    const Vec q = s.pose.inverse() * p;
    if (s.kind == Solid::Kind::kMesh) {
      const std::vector<Vec> v = posed_vertices(s);
      for (const Eigen::Vector3i& t : s.mesh->triangles) d = std::min(d, (p - closest_on_triangle(p, v[t[0]], v[t[1]], v[t[2]])).norm());
    } else if (s.kind == Solid::Kind::kSphere) {
      d = std::min(d, std::max(0.0, q.norm() - s.radius));
    } else if (s.kind == Solid::Kind::kBox) {
      d = std::min(d, (q - q.cwiseMax(-s.size / 2).cwiseMin(s.size / 2)).norm());
    } else {
      const double radial = std::max(0.0, q.head<2>().norm() - s.radius), axial = std::max(0.0, std::abs(q.z()) - s.length / 2);
      d = std::min(d, std::hypot(radial, axial));
    }
  }
  return d;
}

// Radius + distance to the link's solids is within the report's bound; a generated sphere (`touching`)
// also holds a point of them.
void expect_tight(const ArmModel& model, const SphereCover& cover, int max_per_link, bool touching = true) {
  for (const LinkCoverReport& r : cover.links) {
    const std::vector<LinkSphere> mine = of_link(cover.spheres, r.link);
    EXPECT_EQ(r.spheres, static_cast<int>(mine.size()));
    EXPECT_LE(r.spheres, max_per_link + static_cast<int>(model.link(r.link).collision.size()));
    double volume = 0.0;
    for (const LinkSphere& s : mine) {
      const double d = distance_to_solids(s.center, model.link(r.link).collision);
      if (touching) {
        EXPECT_LE(d, s.radius + 1e-12) << model.link(r.link).name << " sphere at " << s.center.transpose();
      }
      // A sphere that is one of the link's sphere solids adds no excess at all.
      const bool solid = std::any_of(model.link(r.link).collision.begin(), model.link(r.link).collision.end(), [&](const Solid& x) {
        return x.kind == Solid::Kind::kSphere && x.pose.translation() == s.center && x.radius == s.radius;
      });
      EXPECT_LE(solid ? 0.0 : s.radius + d, r.excess_bound + 1e-12) << model.link(r.link).name;
      volume += 4.0 / 3.0 * std::numbers::pi * std::pow(s.radius, 3);
    }
    EXPECT_NEAR(r.sphere_volume, volume, 1e-12);
    EXPECT_GT(r.box_volume, 0.0);
  }
}

void expect_same(const SphereCover& a, const SphereCover& b) {
  ASSERT_EQ(a.spheres.size(), b.spheres.size());
  for (std::size_t i = 0; i < a.spheres.size(); ++i) {
    EXPECT_EQ(a.spheres[i].link, b.spheres[i].link);
    EXPECT_EQ(a.spheres[i].center, b.spheres[i].center);
    EXPECT_EQ(a.spheres[i].radius, b.spheres[i].radius);
  }
  ASSERT_EQ(a.links.size(), b.links.size());
  for (std::size_t i = 0; i < a.links.size(); ++i) {
    EXPECT_EQ(a.links[i].link, b.links[i].link);
    EXPECT_EQ(a.links[i].excess_bound, b.links[i].excess_bound);
    EXPECT_EQ(a.links[i].box_volume, b.links[i].box_volume);
  }
}

class ScratchDir {
 public:
  ScratchDir() : path_(fs::temp_directory_path() / ("amp-sphere-test-" + std::to_string(::getpid()))) { fs::create_directories(path_); }
  ~ScratchDir() { fs::remove_all(path_); }
  const fs::path& path() const { return path_; }
  fs::path write(const std::string& name, const std::string& text) const {
    std::ofstream(path_ / name) << text;
    return path_ / name;
  }

 private:
  fs::path path_;
};

std::string read(const fs::path& f) {
  std::ifstream in(f);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A base with a box and a cylinder, a link with a sphere, and a link with no collision geometry.
ArmModel primitives_arm() {
  const Eigen::Isometry3d tilted(Eigen::Translation3d(0.02, -0.01, 0.1) * Eigen::AngleAxisd(0.4, Vec(1, 2, 3).normalized()));
  std::vector<ArmLink> links(3);
  links[0] = {"base", -1, {0}, {Solid::box(Vec(0.11, 0.07, 0.043)), Solid::cylinder(0.035, 0.12, tilted)}};
  links[1] = {"ball", 0, {1}, {Solid::sphere(0.03, Vec(0.1, 0, 0))}};
  links[2] = {"bare", 1, {}, {}};
  std::vector<ArmJoint> joints(2);
  joints[0] = {"j0", ArmJointType::kRevolute, 0, 1};
  joints[1] = {"j1", ArmJointType::kFixed, 1, 2};
  return ArmModel("primitives", std::move(links), std::move(joints));
}

// The `v` lines of the OBJ file that a Panda link's <collision> names.
std::vector<Vec> obj_vertices(const std::string& urdf, const std::string& link) {
  const std::size_t name = urdf.find("meshes/collision/", urdf.find("<collision>", urdf.find("<link name=\"" + link + "\"")));
  std::ifstream in(panda_dir() / urdf.substr(name, urdf.find('"', name) - name));
  std::vector<Vec> out;
  for (std::string line; std::getline(in, line);) {
    if (!line.starts_with("v ")) continue;
    std::istringstream fields(line.substr(2));
    Vec& v = out.emplace_back();
    fields >> v.x() >> v.y() >> v.z();
  }
  return out;
}

class PandaSpheres : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    model_ = std::make_unique<ArmModel>(load_urdf(panda_dir() / "panda.urdf"));
    cover_ = std::make_unique<SphereCover>(cached_cover_with_spheres(*model_, test::shared_sphere_cache()));
  }
  static void TearDownTestSuite() { model_.reset(), cover_.reset(); }
  static inline std::unique_ptr<ArmModel> model_;
  static inline std::unique_ptr<SphereCover> cover_;
};

TEST_F(PandaSpheres, CoverHoldsEveryMeshTriangle) {
  expect_cover(*model_, cover_->spheres);
  for (const LinkCoverReport& r : cover_->links) {
    double largest = 0.0;
    for (const LinkSphere& s : of_link(cover_->spheres, r.link)) largest = std::max(largest, s.radius);
    std::printf("%-18s %2d spheres, largest radius %.4f m, excess <= %.4f m\n", model_->link(r.link).name.c_str(), r.spheres, largest,
                r.excess_bound);
  }
  std::printf("total %zu spheres\n", cover_->spheres.size());
  EXPECT_EQ(cover_->links.size(), 11u);  // panda_link8 and panda_grasptarget have no geometry
}

// The proof can fail: each link's spheres shrunk by a millimetre leave some of its surface out.
TEST_F(PandaSpheres, CheckerFindsTheGapsOfShrunkSpheres) {
  for (const LinkCoverReport& r : cover_->links) {
    std::vector<LinkSphere> shrunk = of_link(cover_->spheres, r.link);
    for (LinkSphere& s : shrunk) s.radius -= 1e-3;
    EXPECT_GT(uncovered(model_->link(r.link).collision, shrunk), 0) << model_->link(r.link).name;
  }
}

TEST_F(PandaSpheres, SpheresTouchTheirLinkAndRespectTheCap) { expect_tight(*model_, *cover_, SphereCoverOptions{}.max_per_link); }

TEST_F(PandaSpheres, SameInputSameSpheres) { expect_same(*cover_, cover_with_spheres(*model_)); }

TEST_F(PandaSpheres, SpherizedUrdfCoversOnlyOnceInflated) {
  const std::vector<LinkSphere> given = load_sphere_urdf(panda_dir() / "panda_spherized.urdf", *model_);
  ASSERT_EQ(given.size(), 59u);
  EXPECT_TRUE(std::is_sorted(given.begin(), given.end(), [](const LinkSphere& a, const LinkSphere& b) { return a.link < b.link; }));
  // Over the OBJ files' own vertices (`v` lines; assimp repeats a vertex per normal), as the README
  // counts them: 1,745 of 4,218 outside.
  const std::string urdf = read(panda_dir() / "panda.urdf");
  int outside = 0, vertices = 0;
  for (int l = 0; l < static_cast<int>(model_->links().size()); ++l) {
    const std::vector<Solid>& solids = model_->link(l).collision;
    if (solids.empty()) continue;
    ASSERT_EQ(solids.size(), 1u);
    for (const Vec& p : obj_vertices(urdf, model_->link(l).name)) outside += in_any(solids[0].pose * p, of_link(given, l)) ? 0 : 1, ++vertices;
  }
  EXPECT_EQ(vertices, 4218);
  EXPECT_GT(outside, 1000);
  EXPECT_EQ(outside, 1745);
  std::printf("%d of %d mesh vertices outside the spherized set\n", outside, vertices);

  const SphereCover inflated = inflate_to_cover(*model_, given, "panda_spherized.urdf");
  ASSERT_EQ(inflated.spheres.size(), given.size());
  for (std::size_t i = 0; i < given.size(); ++i) {
    EXPECT_EQ(inflated.spheres[i].center, given[i].center);
    EXPECT_GE(inflated.spheres[i].radius, given[i].radius);
  }
  expect_cover(*model_, inflated.spheres);
  expect_tight(*model_, inflated, 18, false);
  ASSERT_FALSE(inflated.links.empty());
  EXPECT_EQ(inflated.links[0].link, model_->link_index("panda_link0"));
  EXPECT_GT(inflated.links[0].inflation, 0.0);
}

TEST_F(PandaSpheres, LinkWithSolidsButNoSphereIsRefused) {
  std::vector<LinkSphere> given = cover_->spheres;
  const int link3 = model_->link_index("panda_link3");
  std::erase_if(given, [&](const LinkSphere& s) { return s.link == link3; });
  try {
    inflate_to_cover(*model_, given, "my.urdf");
    FAIL() << "no error";
  } catch (const ParameterError& e) {
    EXPECT_NE(std::string(e.what()).find("link 'panda_link3' has collision geometry but no sphere in my.urdf"), std::string::npos) << e.what();
  }
}

TEST(SphereCover, BoxCylinderAndSphereSolidsAreCovered) {
  const ArmModel model = primitives_arm();
  const SphereCoverOptions options{.piece_size = 0.01, .max_per_link = 6, .bulge = 0.1};
  const SphereCover cover = cover_with_spheres(model, options);
  expect_cover(model, cover.spheres);
  expect_tight(model, cover, options.max_per_link);
  ASSERT_EQ(cover.links.size(), 2u);  // "bare" has none, and no error
  EXPECT_TRUE(of_link(cover.spheres, 2).empty());
  // The sphere solid is kept exactly, and adds no excess.
  const std::vector<LinkSphere> ball = of_link(cover.spheres, 1);
  ASSERT_EQ(ball.size(), 1u);
  EXPECT_EQ(ball[0].center, Vec(0.1, 0, 0));
  EXPECT_EQ(ball[0].radius, 0.03);
  EXPECT_EQ(cover.links[1].excess_bound, 0.0);
  // A one-sphere set of the base grows to the whole base; the sphere of "bare" is kept as given.
  const SphereCover grown = inflate_to_cover(model, {{0, Vec::Zero(), 0.01}, {1, Vec(0.1, 0, 0), 0.03}, {2, Vec::Ones(), 0.5}}, "set");
  expect_cover(model, grown.spheres);
  EXPECT_EQ(grown.spheres[2].radius, 0.5);
  EXPECT_NEAR(grown.links[0].inflation, grown.spheres[0].radius - 0.01, 1e-15);
}

TEST(SphereUrdf, UnknownLinkAndNonSphereCollisionAreFileErrors) {
  const ArmModel model = primitives_arm();
  const ScratchDir dir;
  const auto urdf = [](const std::string& link, const std::string& geometry) {
    return "<robot name='r'><link name='" + link + "'><collision><geometry>" + geometry + "</geometry></collision></link></robot>";
  };
  const auto message = [&](const std::string& text) {
    const fs::path file = dir.write("s.urdf", text);
    try {
      load_sphere_urdf(file, model);
    } catch (const FileError& e) {
      EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(urdf("elbow", "<sphere radius='0.1'/>")).find("'elbow'"), std::string::npos);
  const std::string box = message(urdf("base", "<box size='1 1 1'/>"));
  EXPECT_NE(box.find("'base'"), std::string::npos) << box;
  EXPECT_NE(box.find("box"), std::string::npos) << box;
  const std::vector<LinkSphere> ok = load_sphere_urdf(dir.write("ok.urdf", urdf("base", "<sphere radius='0.2'/>")), model);
  ASSERT_EQ(ok.size(), 1u);
  EXPECT_EQ(ok[0].link, 0);
  EXPECT_EQ(ok[0].radius, 0.2);
}

// Under the sanitizers the cache is exercised on the small hand-made arm, whose cover generates in
// a fraction of the Panda's time (the test generates three covers); the Release build uses the Panda.
TEST_F(PandaSpheres, CacheWritesOnceAndReadsBack) {
  const ScratchDir dir;
  const fs::path cache = dir.path() / "cache";
  const ArmModel small = primitives_arm();
  const ArmModel& model = test::kSanitizerBuild ? small : *model_;
  const SphereCover reference = test::kSanitizerBuild ? cover_with_spheres(small) : *cover_;
  ASSERT_FALSE(reference.spheres.empty());
  expect_same(cached_cover_with_spheres(model, cache), reference);
  const std::vector<fs::path> files{fs::directory_iterator(cache), fs::directory_iterator()};
  ASSERT_EQ(files.size(), 1u);
  EXPECT_TRUE(files[0].filename().string().starts_with("spheres-"));
  const std::string text = read(files[0]);
  EXPECT_EQ(text, format_sphere_cache(reference, model));
  expect_same(cached_cover_with_spheres(model, cache), reference);

  // What is read back is the file (an edited radius comes back) ...
  const std::string r = "sphere " + model.link(reference.spheres[0].link).name + " ";
  const std::size_t line = text.find(r), end = text.find('\n', line), last = text.rfind(' ', end);
  ASSERT_NE(line, std::string::npos) << r;
  std::ofstream(files[0]) << text.substr(0, last) + " 0.5" + text.substr(end);
  EXPECT_EQ(cached_cover_with_spheres(model, cache).spheres[0].radius, 0.5);
  // ... unless it is not a number, which regenerates and rewrites the entry.
  std::ofstream(files[0]) << text.substr(0, last) + " 0.5x" + text.substr(end);
  expect_same(cached_cover_with_spheres(model, cache), reference);
  EXPECT_EQ(read(files[0]), text);
  // Other options are another entry.
  cached_cover_with_spheres(model, cache, SphereCoverOptions{.piece_size = 0.02});
  EXPECT_EQ(std::distance(fs::directory_iterator(cache), fs::directory_iterator()), 2);
}

TEST_F(PandaSpheres, CacheParserRefusesDamagedEntries) {
  const std::string text = format_sphere_cache(*cover_, *model_);
  SphereCover back;
  ASSERT_TRUE(parse_sphere_cache(text, *model_, back));
  expect_same(back, *cover_);
  const auto replaced = [&](const std::string& from, const std::string& to) {
    std::string t = text;
    const std::size_t at = t.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return t.replace(at, from.size(), to);
  };
  const std::string r0 = text.substr(0, text.find('\n', text.find("\nsphere ") + 1));
  const std::string last_field = r0.substr(r0.rfind(' '));
  const std::vector<std::string> bad{
      text.substr(0, text.size() / 2),
      text.substr(0, text.size() - 1),
      replaced(last_field + "\n", " nan\n"),
      replaced(last_field + "\n", " -0.01\n"),
      replaced(last_field + "\n", " 0\n"),
      replaced("sphere panda_link0 ", "sphere panda_link9 "),
      replaced("amp-sphere-cover 1 ", "amp-sphere-cover 1 f"),
      replaced("\nend\n", "\nend\nend\n"),
      replaced("link panda_link0 ", "link panda_link1 "),
  };
  for (const std::string& b : bad) {
    SphereCover untouched;
    EXPECT_FALSE(parse_sphere_cache(b, *model_, untouched)) << b.substr(0, 200);
    EXPECT_TRUE(untouched.spheres.empty());
  }
  // A key that belongs to other options (the key line altered by one digit).
  std::string key = text;
  key[19] = key[19] == '0' ? '1' : '0';
  EXPECT_FALSE(parse_sphere_cache(key, *model_, back));
}

TEST(SphereCacheDir, FollowsTheEnvironment) {
  const char* names[] = {"AMP_CACHE_DIR", "XDG_CACHE_HOME", "HOME"};
  std::vector<std::pair<bool, std::string>> saved;
  for (const char* n : names) saved.emplace_back(std::getenv(n) != nullptr, std::getenv(n) ? std::getenv(n) : "");
  for (const char* n : names) ::unsetenv(n);
  EXPECT_TRUE(default_sphere_cache_dir().empty());
  ::setenv("HOME", "/h", 1);
  EXPECT_EQ(default_sphere_cache_dir(), fs::path("/h/.cache/amp"));
  ::setenv("XDG_CACHE_HOME", "/x", 1);
  EXPECT_EQ(default_sphere_cache_dir(), fs::path("/x/amp"));
  ::setenv("AMP_CACHE_DIR", "/a", 1);
  EXPECT_EQ(default_sphere_cache_dir(), fs::path("/a"));
  for (std::size_t i = 0; i < saved.size(); ++i) {
    if (saved[i].first) ::setenv(names[i], saved[i].second.c_str(), 1);
    else ::unsetenv(names[i]);
  }
}

}  // namespace
}  // namespace amp::world
