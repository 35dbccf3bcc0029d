#include "amp/learn/centre_triangulation.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

namespace amp::learn {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase>;
using Delaunay = CGAL::Delaunay_triangulation_2<Kernel, Tds>;
using Point = Kernel::Point_2;
using Vertex = Delaunay::Vertex_handle;

Point to_point(const Eigen::Vector2d& p) { return Point(p.x(), p.y()); }

}  // namespace

struct CentreTriangulation::Impl {
  Delaunay dt;
  std::vector<Vertex> handle;  // by id; null when absent or hidden
  std::vector<Point> pos;      // by id
  std::vector<char> present;   // by id
  std::vector<int> hidden;     // ids kept out as duplicates (usually empty)
  int count = 0;

  void check_present(int id, const char* what) const {
    if (id < 0 || id >= static_cast<int>(present.size()) || !present[id]) {
      throw std::invalid_argument(std::string("centre triangulation: ") + what + " of absent id " + std::to_string(id));
    }
  }

  // Inserts id at pos[id], or hides it when a triangulated centre is already there.
  void show(int id) {
    const auto before = dt.number_of_vertices();
    const Vertex v = dt.insert(pos[id]);
    if (dt.number_of_vertices() == before) {
      hidden.push_back(id);
      return;
    }
    v->info() = id;
    handle[id] = v;
  }

  // After the triangulated centre at `p` left, the first hidden centre at p takes its place.
  void reveal_at(const Point& p) {
    for (std::size_t i = 0; i < hidden.size(); ++i) {
      const int h = hidden[i];
      if (pos[h] == p) {
        hidden.erase(hidden.begin() + static_cast<std::ptrdiff_t>(i));
        show(h);
        return;
      }
    }
  }

  void unhide(int id) { hidden.erase(std::find(hidden.begin(), hidden.end(), id)); }
};

CentreTriangulation::CentreTriangulation() : impl_(std::make_unique<Impl>()) {}
CentreTriangulation::~CentreTriangulation() = default;
CentreTriangulation::CentreTriangulation(CentreTriangulation&&) noexcept = default;
CentreTriangulation& CentreTriangulation::operator=(CentreTriangulation&&) noexcept = default;

void CentreTriangulation::insert(int id, const Eigen::Vector2d& p) {
  Impl& m = *impl_;
  if (id < 0) throw std::invalid_argument("centre triangulation: negative id " + std::to_string(id));
  if (id >= static_cast<int>(m.present.size())) {
    const std::size_t n = std::max<std::size_t>(static_cast<std::size_t>(id) + 1, 2 * m.present.size());
    m.handle.resize(n);
    m.pos.resize(n);
    m.present.resize(n, 0);
  }
  if (m.present[id]) throw std::invalid_argument("centre triangulation: id " + std::to_string(id) + " inserted twice");
  m.present[id] = 1;
  m.pos[id] = to_point(p);
  m.handle[id] = Vertex();
  ++m.count;
  m.show(id);
}

void CentreTriangulation::move(int id, const Eigen::Vector2d& p) {
  Impl& m = *impl_;
  m.check_present(id, "move");
  const Point to = to_point(p);
  const Point from = m.pos[id];
  if (to == from) return;
  m.pos[id] = to;
  const Vertex v = m.handle[id];
  if (v == Vertex()) {  // a hidden duplicate moves: try to insert it where it now is
    m.unhide(id);
    m.show(id);
    return;
  }
  if (m.dt.move_if_no_collision(v, to) != v) {  // lands on another centre: hide it there
    m.dt.remove(v);
    m.handle[id] = Vertex();
    m.hidden.push_back(id);
  }
  if (!m.hidden.empty()) m.reveal_at(from);
}

void CentreTriangulation::remove(int id) {
  Impl& m = *impl_;
  m.check_present(id, "remove");
  m.present[id] = 0;
  --m.count;
  const Vertex v = m.handle[id];
  if (v == Vertex()) {
    m.unhide(id);
    return;
  }
  m.dt.remove(v);
  m.handle[id] = Vertex();
  if (!m.hidden.empty()) m.reveal_at(m.pos[id]);
}

bool CentreTriangulation::contains(int id) const {
  return id >= 0 && id < static_cast<int>(impl_->present.size()) && impl_->present[id];
}

bool CentreTriangulation::hidden(int id) const { return contains(id) && impl_->handle[id] == Vertex(); }

int CentreTriangulation::size() const { return impl_->count; }

void CentreTriangulation::neighbours(int id, std::vector<int>& out) const {
  const Impl& m = *impl_;
  out.clear();
  m.check_present(id, "neighbours");
  const Vertex v = m.handle[id];
  if (v == Vertex() || m.dt.dimension() < 1) return;
  Delaunay::Vertex_circulator c = m.dt.incident_vertices(v), done = c;
  if (c == nullptr) return;
  do {
    if (!m.dt.is_infinite(c)) out.push_back(c->info());
  } while (++c != done);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

std::vector<std::pair<int, int>> CentreTriangulation::edges() const {
  std::vector<std::pair<int, int>> out;
  const Delaunay& dt = impl_->dt;
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
    const int a = e->first->vertex(Delaunay::cw(e->second))->info();
    const int b = e->first->vertex(Delaunay::ccw(e->second))->info();
    out.emplace_back(std::min(a, b), std::max(a, b));
  }
  std::sort(out.begin(), out.end());
  return out;
}

int CentreTriangulation::nearest(const Eigen::Vector2d& p) const {
  const Delaunay& dt = impl_->dt;
  if (dt.number_of_vertices() == 0) return -1;
  return dt.nearest_vertex(to_point(p))->info();
}

}  // namespace amp::learn
