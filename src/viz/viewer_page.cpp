#include "amp/viz/viewer_page.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>

#include "amp/core/error.hpp"
#include "amp/roadmap/path_certificate.hpp"
#include "amp/viz/mesh_decimation.hpp"
#include "amp/viz/xml_escape.hpp"
#include "viewer/page_buffer.hpp"
#include "viewer/viewer_assets.hpp"

namespace amp::viz {

namespace {

using detail::PageBuffer;
using nlohmann::json;

// Bytes a triangle costs in the page, with about one vertex per triangle (12 + 12 bytes), once
// base64 has made 4 characters of every 3 bytes: what the decimation budget is counted in.
constexpr double kPageBytesPerTriangle = 24.0 * 4.0 / 3.0;
// However tight the budget, a page keeps this many triangles: a world still recognisable.
constexpr std::size_t kMinTriangles = 2000;

// A mesh appended to the buffer: [offset, count] of its vertices and of its triangles.
json append_mesh(PageBuffer& buffer, const world::TriangleMesh& mesh) {
  std::vector<float> xyz;
  xyz.reserve(mesh.vertices.size() * 3);
  for (const Eigen::Vector3d& v : mesh.vertices) {
    for (int k = 0; k < 3; ++k) xyz.push_back(static_cast<float>(v[k]));
  }
  std::vector<std::uint32_t> corners;
  corners.reserve(mesh.triangles.size() * 3);
  for (const Eigen::Vector3i& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) corners.push_back(static_cast<std::uint32_t>(t[k]));
  }
  const std::size_t vertices_at = buffer.append(xyz);
  const std::size_t triangles_at = buffer.append(corners);
  return json{{"vertices", {vertices_at, mesh.vertices.size()}}, {"triangles", {triangles_at, mesh.triangles.size()}}};
}

// Position and quaternion (x y z qx qy qz qw) of every link at `s`, appended to `out`.
void append_poses(const world::SceneModelSource& source, const State& s, std::vector<Eigen::Isometry3d>& scratch,
                  std::vector<float>& out) {
  source.robot_link_poses(s, scratch);
  for (const Eigen::Isometry3d& pose : scratch) {
    const Eigen::Quaterniond q(pose.rotation());
    const Eigen::Vector3d p = pose.translation();
    for (const double v : {p.x(), p.y(), p.z(), q.x(), q.y(), q.z(), q.w()}) out.push_back(static_cast<float>(v));
  }
}

std::vector<float> points_of(const std::vector<Eigen::Vector3d>& points) {
  std::vector<float> out;
  out.reserve(points.size() * 3);
  for (const Eigen::Vector3d& p : points) {
    for (int k = 0; k < 3; ++k) out.push_back(static_cast<float>(p[k]));
  }
  return out;
}

std::vector<Eigen::Vector3d> roadmap_segments(const world::Problem& problem, const RoadmapDrawing& roadmap) {
  std::vector<Eigen::Vector3d> ends;
  ends.reserve(roadmap.edges.size() * 2);
  for (const auto& [a, b] : roadmap.edges) {
    ends.push_back(problem.environment->reference_point(roadmap.vertices[a]));
    ends.push_back(problem.environment->reference_point(roadmap.vertices[b]));
  }
  return ends;
}

std::size_t triangle_count(const world::SceneModel& model) {
  std::size_t n = 0;
  for (const auto& m : model.obstacles) n += m.triangles.size();
  for (const auto& m : model.robot_links) n += m.triangles.size();
  return n;
}

// Simplifies the meshes when the page would pass its size budget; returns what the page says about
// it (empty when nothing was simplified).
std::string fit_meshes(world::SceneModel& model, std::size_t fixed_bytes, std::size_t max_bytes) {
  const double room = static_cast<double>(max_bytes) - static_cast<double>(fixed_bytes);
  const auto max_triangles = std::max(kMinTriangles, static_cast<std::size_t>(std::max(0.0, room) / kPageBytesPerTriangle));
  std::vector<const world::TriangleMesh*> meshes;
  for (const auto& m : model.obstacles) meshes.push_back(&m);
  for (const auto& m : model.robot_links) meshes.push_back(&m);
  const double cell = decimation_cell(meshes, max_triangles);
  if (cell <= 0.0) return {};
  const std::size_t before = triangle_count(model);
  for (auto& m : model.obstacles) m = cluster_vertices(m, cell);
  for (auto& m : model.robot_links) m = cluster_vertices(m, cell);
  std::ostringstream note;
  note << std::setprecision(3) << "Meshes simplified for display, the page being limited to "
       << static_cast<double>(max_bytes) / 1e6 << " MB (--max-mb): vertex clustering on cubes of side " << cell
       << ", " << before << " triangles shown as " << triangle_count(model)
       << ". Collision checking used the full meshes.";
  return note.str();
}

// Where the camera first looks: at the robot's start and goal placements and the path between
// them (the part of a large world that matters), from the side of the start-to-goal direction,
// so that both ends show across whatever separates them (a wall, a plate with a hole).
struct CameraView {
  Eigen::AlignedBox3d focus;
  Eigen::Vector3d direction;  // from the focus towards the camera
};

CameraView camera_view(const world::SceneModel& model, const world::SceneModelSource& source, const State& start,
                       const State& goal, const std::vector<Eigen::Vector3d>& trace) {
  const Eigen::Vector3d preferred = Eigen::Vector3d(0.75, -1.1, 0.7).normalized();  // front, right, above
  if (model.flat) return {model.bounds, Eigen::Vector3d(0.0, -0.45, 1.0).normalized()};
  CameraView view{Eigen::AlignedBox3d(), preferred};
  std::vector<Eigen::Isometry3d> poses;
  for (const State* s : {&start, &goal}) {
    source.robot_link_poses(*s, poses);
    for (std::size_t i = 0; i < poses.size() && i < model.robot_links.size(); ++i) {
      for (const Eigen::Vector3d& v : model.robot_links[i].vertices) view.focus.extend(poses[i] * v);
    }
  }
  for (const Eigen::Vector3d& p : trace) view.focus.extend(p);
  if (view.focus.isEmpty()) view.focus = model.bounds;
  const Eigen::Vector3d along = trace.back() - trace.front();
  if (along.norm() > 1e-9 * std::max(1.0, view.focus.diagonal().norm())) {
    const Eigen::Vector3d d = along.normalized();
    const Eigen::Vector3d side = preferred - preferred.dot(d) * d;  // the preferred view, turned square to d
    if (side.norm() > 0.1) view.direction = side.normalized();
  }
  // Neither level (a world seen edge-on looks flat) nor steep (an arm seen from above hides its
  // reach): the elevation is kept between about 17 and 37 degrees.
  Eigen::Vector2d level = view.direction.head<2>();
  if (level.norm() < 1e-6) level = preferred.head<2>();
  const double z = std::clamp(view.direction.z(), 0.3, 0.6);
  view.direction << level.normalized() * std::sqrt(1.0 - z * z), z;
  return view;
}

std::string three_revision() {
  const std::string_view key = "REVISION=\"";
  const std::size_t at = detail::kThreeJs.find(key);
  if (at == std::string_view::npos) return "?";
  const std::size_t from = at + key.size();
  return std::string(detail::kThreeJs.substr(from, detail::kThreeJs.find('"', from) - from));
}

// The template with each @AMP_…@ key replaced, in one pass over the template only: no inserted
// text (a title, three.js) is searched again.
std::string expand_template(std::string_view text, const std::map<std::string_view, std::string_view>& values) {
  std::string out;
  std::size_t pos = 0;
  for (std::size_t at = text.find("@AMP_"); at != std::string_view::npos; at = text.find("@AMP_", pos)) {
    const std::size_t end = text.find('@', at + 1);
    const auto it = values.find(text.substr(at, end == std::string_view::npos ? end : end - at + 1));
    if (it == values.end()) throw Error("the viewer's page template has an unknown key at byte " + std::to_string(at));
    out.append(text.substr(pos, at - pos)).append(it->second);
    pos = end + 1;
  }
  return out.append(text.substr(pos));
}

// JSON inside a <script> element: "</" would end the element, "<\/" is the same JSON string.
std::string script_safe(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    out.push_back(text[i]);
    if (text[i] == '<' && i + 1 < text.size() && text[i + 1] == '/') out.push_back('\\');
  }
  return out;
}

// The motion data: per frame each link's pose, the start and goal poses, the reference point's
// trace, the roadmap's segments; returns their layout and fills `trace`.
json motion_data(const world::Problem& problem, const std::vector<State>& frames, const RoadmapDrawing* roadmap,
                 PageBuffer& motion, std::vector<Eigen::Vector3d>& trace) {
  const world::Environment& env = *problem.environment;
  std::vector<Eigen::Isometry3d> scratch;
  std::vector<float> poses, start_pose, goal_pose;
  for (const State& s : frames) {
    append_poses(env, s, scratch, poses);
    trace.push_back(env.reference_point(s));
  }
  append_poses(env, problem.start(), scratch, start_pose);
  append_poses(env, problem.goal(), scratch, goal_pose);
  json meta;
  meta["poses"] = {{"offset", motion.append(poses)}, {"frames", frames.size()}};
  meta["start"] = motion.append(start_pose);
  meta["goal"] = motion.append(goal_pose);
  meta["trace"] = {motion.append(points_of(trace)), trace.size()};
  if (roadmap != nullptr) {
    const auto ends = roadmap_segments(problem, *roadmap);
    meta["roadmap"] = {motion.append(points_of(ends)), ends.size()};
  }
  return meta;
}

// The meshes into the buffer, and their layout into meta's "obstacles" and "links".
void mesh_data(const world::SceneModel& model, PageBuffer& buffer, json& meta) {
  json obstacles = json::array(), links = json::array();
  for (const auto& m : model.obstacles) obstacles.push_back(append_mesh(buffer, m));
  for (std::size_t i = 0; i < model.robot_links.size(); ++i) {
    json link = append_mesh(buffer, model.robot_links[i]);
    link["name"] = model.link_names[i];
    links.push_back(link);
  }
  meta["obstacles"] = obstacles;
  meta["links"] = links;
}

void shift_offsets(json& meta, std::size_t shift) {
  meta["poses"]["offset"] = meta["poses"]["offset"].get<std::size_t>() + shift;
  for (const char* key : {"start", "goal"}) meta[key] = meta[key].get<std::size_t>() + shift;
  for (const char* key : {"trace", "roadmap"}) {
    if (meta.contains(key)) meta[key][0] = meta[key][0].get<std::size_t>() + shift;
  }
}

json box_json(const Eigen::AlignedBox3d& b) {
  return {b.min().x(), b.min().y(), b.min().z(), b.max().x(), b.max().y(), b.max().z()};
}

// What the page says above the view: a simplification, no path, a path not certified.
std::vector<std::string> page_notes(const ViewerContent& content, const std::string& mesh_note) {
  std::vector<std::string> notes;
  if (!mesh_note.empty()) notes.push_back(mesh_note);
  if (content.path.empty()) {
    notes.push_back("No path: the robot is shown at the start. Pass --path (a file amp plan --out wrote), or "
                    "--roadmap to plan one.");
  } else if (!content.path_certified) {
    notes.push_back("This path is NOT certified collision-free: " + content.path_failure + ".");
  }
  return notes;
}

std::string page_text(const std::string& title, const std::string& subtitle, const std::vector<std::string>& notes,
                      const json& meta, const std::string& bytes) {
  std::string notes_html;
  for (const std::string& n : notes) notes_html += "<p class=\"note\">" + xml_escape(n) + "</p>\n";
  const std::string title_html = xml_escape(title), subtitle_html = xml_escape(subtitle);
  const std::string revision = three_revision(), scene = script_safe(meta.dump()), data = detail::base64(bytes);
  return expand_template(detail::kViewerHtml, {{"@AMP_TITLE@", title_html},
                                               {"@AMP_SUBTITLE@", subtitle_html},
                                               {"@AMP_NOTES@", notes_html},
                                               {"@AMP_THREE_REVISION@", revision},
                                               {"@AMP_SCENE@", scene},
                                               {"@AMP_DATA@", data},
                                               {"@AMP_THREE@", detail::kThreeJs},
                                               {"@AMP_ORBIT_CONTROLS@", detail::kOrbitControlsJs},
                                               {"@AMP_VIEWER@", detail::kViewerJs}});
}

}  // namespace

ViewerContent path_content(const world::Problem& problem, std::vector<State> path, const std::string& source) {
  ViewerContent content;
  content.subtitle = source;
  if (!path.empty()) {
    const roadmap::PathCertificate certificate = roadmap::certify_path(*problem.space, *problem.environment, path);
    content.path_certified = certificate.certified;
    content.path_failure = certificate.failure;
    content.subtitle += (source.empty() ? "" : " · ") + std::to_string(path.size()) + " waypoints, " +
                        (certificate.certified ? "certified collision-free along its whole length"
                                               : "NOT certified collision-free");
  }
  content.path = std::move(path);
  return content;
}

std::vector<State> viewer_frames(const core::Space& space, const std::vector<State>& path, std::size_t frames) {
  if (path.size() < 2) return path;
  double total = 0.0;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) total += space.distance(path[i], path[i + 1]);
  std::vector<State> out{path.front()};
  State between;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const double share = total > 0.0 ? space.distance(path[i], path[i + 1]) / total : 0.0;
    const auto steps = std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(share * static_cast<double>(frames))));
    for (std::size_t k = 1; k < steps; ++k) {
      space.interpolate(path[i], path[i + 1], static_cast<double>(k) / static_cast<double>(steps), between);
      out.push_back(between);
    }
    out.push_back(path[i + 1]);
  }
  return out;
}

std::string viewer_page(const world::Problem& problem, const ViewerContent& content) {
  const world::Environment& env = *problem.environment;
  world::SceneModel model = env.scene_model();
  const std::vector<State> frames =
      viewer_frames(*problem.space, content.path.empty() ? std::vector<State>{problem.start()} : content.path,
                    content.frames);
  // Everything but the meshes first: its size sets what room the meshes have.
  PageBuffer motion;
  std::vector<Eigen::Vector3d> trace;
  json meta = motion_data(problem, frames, content.roadmap, motion, trace);
  const std::size_t fixed_bytes = detail::kThreeJs.size() + detail::kOrbitControlsJs.size() +
                                  detail::kViewerJs.size() + detail::kViewerHtml.size() + motion.size() * 4 / 3;
  const std::vector<std::string> notes = page_notes(content, fit_meshes(model, fixed_bytes, content.max_bytes));

  // The meshes come first in the one buffer: the motion data's offsets move past them.
  PageBuffer buffer;
  mesh_data(model, buffer, meta);
  shift_offsets(meta, buffer.size());
  meta["bounds"] = box_json(model.bounds);
  meta["flat"] = model.flat;
  const CameraView view = camera_view(model, env, problem.start(), problem.goal(), trace);
  meta["focus"] = box_json(view.focus);
  meta["view"] = {view.direction.x(), view.direction.y(), view.direction.z()};
  meta["notes"] = notes;
  return page_text(content.title.empty() ? problem.name : content.title, content.subtitle, notes, meta,
                   buffer.bytes() + motion.bytes());
}

}  // namespace amp::viz
