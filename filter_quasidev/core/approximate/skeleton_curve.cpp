// Skeleton ordering by minimum spanning tree; see skeleton_curve.h.
#include "approximate/skeleton_curve.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

namespace qd::approximate {

namespace {

// Neighbour window (Chebyshev radius in pixels). 2 instead of the 8-neighbourhood's 1 bridges
// the one-pixel breaks that sub-pixel ridge detection leaves on diagonal ridges.
constexpr int kWindow = 2;
// Skeleton components whose field mass is below this fraction of the strongest one are
// outlier blobs and are dropped before the components are joined.
constexpr double kWeakComponent = 0.05;
// A periodic path spanning this fraction of the period without a closing loop is still a tube.
constexpr double kTubeSpan = 0.75;
// The prolongation of an open curve's end reaches this quantile of the samples beyond the end
// and turns by at most kMaxTurn.
constexpr double kEndQuantile = 0.98;
constexpr double kMaxTurn = 0.25 * 3.14159265358979323846;

struct Edge {
  double w;
  int a, b;
  bool operator<(const Edge& o) const { return std::tie(w, a, b) < std::tie(o.w, o.a, o.b); }
};

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(int n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  bool unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    parent[std::max(a, b)] = std::min(a, b);
    return true;
  }
};

// Difference b − a with x wrapped into [−period/2, period/2] (period 0: no wrap).
Vec2 delta(const Vec2& a, const Vec2& b, double period) {
  Vec2 d = b - a;
  if (period > 0) d.x() -= period * std::round(d.x() / period);
  return d;
}

// Graph edges between points whose pixels are within the window.
std::vector<Edge> window_edges(const std::vector<SkeletonPoint>& pts, int width, bool periodic) {
  int height = 0;
  for (const SkeletonPoint& p : pts) height = std::max(height, p.y + 1);
  std::vector<int> at(static_cast<size_t>(width) * height, -1);
  for (size_t i = 0; i < pts.size(); ++i)
    at[static_cast<size_t>(pts[i].y) * width + pts[i].x] = static_cast<int>(i);
  const double period = periodic ? width : 0.0;
  std::vector<Edge> edges;
  for (size_t i = 0; i < pts.size(); ++i)
    for (int dy = -kWindow; dy <= kWindow; ++dy)
      for (int dx = -kWindow; dx <= kWindow; ++dx) {
        int x = pts[i].x + dx;
        const int y = pts[i].y + dy;
        if (periodic) x = (x + width) % width;
        if (y < 0 || y >= height || x < 0 || x >= width) continue;
        const int j = at[static_cast<size_t>(y) * width + x];
        if (j > static_cast<int>(i))
          edges.push_back({delta(pts[i].pos, pts[j].pos, period).norm(), static_cast<int>(i), j});
      }
  return edges;
}

// Keeps the points of components (under `edges`) that are not weak; remaps the edges.
void drop_weak_components(std::vector<SkeletonPoint>& pts, std::vector<Edge>& edges) {
  const int n = static_cast<int>(pts.size());
  UnionFind uf(n);
  for (const Edge& e : edges) uf.unite(e.a, e.b);
  std::vector<double> mass(n, 0.0);
  for (int i = 0; i < n; ++i) mass[uf.find(i)] += pts[i].strength;
  const double strongest = *std::max_element(mass.begin(), mass.end());
  std::vector<int> index(n, -1);
  std::vector<SkeletonPoint> kept;
  for (int i = 0; i < n; ++i)
    if (mass[uf.find(i)] >= kWeakComponent * strongest) {
      index[i] = static_cast<int>(kept.size());
      kept.push_back(pts[i]);
    }
  std::vector<Edge> remapped;
  for (const Edge& e : edges)
    if (index[e.a] >= 0 && index[e.b] >= 0) remapped.push_back({e.w, index[e.a], index[e.b]});
  pts.swap(kept);
  edges.swap(remapped);
}

// Kruskal minimum spanning tree over `edges`, then the shortest links between the remaining
// components (so separate blobs of a coarse mesh's Gauss image are chained). Returns the tree
// adjacency; edges not in the tree are appended to `unused`.
std::vector<std::vector<std::pair<int, double>>> spanning_tree(
    const std::vector<SkeletonPoint>& pts, std::vector<Edge> edges, double period,
    std::vector<Edge>& unused) {
  const int n = static_cast<int>(pts.size());
  std::vector<std::vector<std::pair<int, double>>> adj(n);
  UnionFind uf(n);
  auto kruskal = [&](std::vector<Edge>& list) {
    std::sort(list.begin(), list.end());
    for (const Edge& e : list) {
      if (uf.unite(e.a, e.b)) {
        adj[e.a].push_back({e.b, e.w});
        adj[e.b].push_back({e.a, e.w});
      } else {
        unused.push_back(e);
      }
    }
  };
  kruskal(edges);
  std::vector<int> roots;
  for (int i = 0; i < n; ++i)
    if (uf.find(i) == i) roots.push_back(i);
  if (roots.size() < 2) return adj;
  std::vector<int> comp(n);
  for (int i = 0; i < n; ++i)
    comp[i] =
        static_cast<int>(std::lower_bound(roots.begin(), roots.end(), uf.find(i)) - roots.begin());
  const size_t c = roots.size();
  std::vector<Edge> best(c * c, Edge{1e300, -1, -1});
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      if (comp[i] == comp[j]) continue;
      const Edge e{delta(pts[i].pos, pts[j].pos, period).norm(), i, j};
      Edge& slot = best[std::min(comp[i], comp[j]) * c + std::max(comp[i], comp[j])];
      if (e < slot) slot = e;
    }
  std::vector<Edge> links;
  for (const Edge& e : best)
    if (e.a >= 0) links.push_back(e);
  kruskal(links);
  return adj;
}

// The first point of the polyline, going back from index `from`, at least `distance` away from
// polyline[from] (or the first point).
Vec2 point_back_from(const std::vector<Vec2>& polyline, size_t from, double distance) {
  for (size_t k = from; k-- > 0;)
    if ((polyline[from] - polyline[k]).norm() >= distance) return polyline[k];
  return polyline.front();
}

Vec2 rotate(const Vec2& v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return Vec2(c * v.x() - s * v.y(), s * v.x() + c * v.y());
}

// Tree walk from `root`: parent, depth, path length and x-unwrapped position of every node.
struct TreeWalk {
  std::vector<int> parent, depth;
  std::vector<double> dist;
  std::vector<Vec2> unwrapped;
};

TreeWalk walk_tree(const std::vector<std::vector<std::pair<int, double>>>& adj,
                   const std::vector<SkeletonPoint>& pts, int root, double period) {
  const size_t n = adj.size();
  TreeWalk t{std::vector<int>(n, -1), std::vector<int>(n, 0), std::vector<double>(n, 0.0),
             std::vector<Vec2>(n, Vec2::Zero())};
  std::vector<int> stack{root};
  t.parent[root] = root;
  t.unwrapped[root] = pts[root].pos;
  while (!stack.empty()) {
    const int u = stack.back();
    stack.pop_back();
    for (const auto& [v, w] : adj[u]) {
      if (t.parent[v] != -1) continue;
      t.parent[v] = u;
      t.depth[v] = t.depth[u] + 1;
      t.dist[v] = t.dist[u] + w;
      t.unwrapped[v] = t.unwrapped[u] + delta(pts[u].pos, pts[v].pos, period);
      stack.push_back(v);
    }
  }
  return t;
}

// Tree path a -> b (inclusive) using the walk's parents.
std::vector<int> tree_path(const TreeWalk& t, int a, int b) {
  std::vector<int> front, back;
  while (t.depth[a] > t.depth[b]) front.push_back(a), a = t.parent[a];
  while (t.depth[b] > t.depth[a]) back.push_back(b), b = t.parent[b];
  while (a != b) {
    front.push_back(a), a = t.parent[a];
    back.push_back(b), b = t.parent[b];
  }
  front.push_back(a);
  front.insert(front.end(), back.rbegin(), back.rend());
  return front;
}

int farthest(const TreeWalk& t) {
  return static_cast<int>(std::max_element(t.dist.begin(), t.dist.end()) - t.dist.begin());
}

}  // namespace

OrderedSkeleton order_skeleton(const std::vector<SkeletonPoint>& input, int width, bool periodic) {
  OrderedSkeleton out;
  if (input.empty()) return out;
  std::vector<SkeletonPoint> pts = input;
  std::vector<Edge> edges = window_edges(pts, width, periodic);
  drop_weak_components(pts, edges);
  const double period = periodic ? width : 0.0;
  std::vector<Edge> unused;
  const auto adj = spanning_tree(pts, edges, period, unused);

  std::vector<int> order;
  const TreeWalk from0 = walk_tree(adj, pts, 0, period);
  if (periodic) {
    // The shortest non-tree edge that closes a loop winding around θ picks the loop.
    const Edge* closing = nullptr;
    for (const Edge& e : unused) {
      const double wind = from0.unwrapped[e.a].x() + delta(pts[e.a].pos, pts[e.b].pos, period).x() -
                          from0.unwrapped[e.b].x();
      if (std::abs(wind) > 0.5 * period && (!closing || e < *closing)) closing = &e;
    }
    if (closing) {
      order = tree_path(from0, closing->a, closing->b);
      out.closed = true;
    }
  }
  if (order.empty()) {  // backbone: the tree's longest path (double sweep)
    const int a = farthest(from0);
    const TreeWalk from_a = walk_tree(adj, pts, a, period);
    order = tree_path(from_a, a, farthest(from_a));
  }
  out.points.reserve(order.size());
  out.points.push_back(pts[order[0]].pos);
  for (size_t k = 1; k < order.size(); ++k)
    out.points.push_back(out.points.back() +
                         delta(pts[order[k - 1]].pos, pts[order[k]].pos, period));
  if (periodic) {
    const double span = out.points.back().x() - out.points.front().x() +
                        delta(out.points.back(), out.points.front(), period).x();
    if (std::abs(span) > kTubeSpan * period) {
      out.closed = true;
      out.shift = Vec2(period * (span > 0 ? 1.0 : -1.0), 0.0);
    } else {
      out.closed = false;
    }
  }
  return out;
}

void extend_ends(std::vector<Vec2>& polyline, const std::vector<Vec2>& samples, double reach,
                 double period, double trim) {
  if (polyline.size() < 2 || (polyline.back() - polyline.front()).norm() < 3 * trim)
    trim = 0;  // too short to spare its ends
  for (int end = 0; end < 2; ++end) {
    if (polyline.size() < 2) return;
    std::reverse(polyline.begin(), polyline.end());  // work on the back, twice
    // Trim: the ridge curls where the point distribution ends; drop the points within `trim`
    // (Euclidean) of the end, so a curl of any path length goes.
    const Vec2 tip = polyline.back();
    while (polyline.size() > 2 && (polyline.back() - tip).norm() < trim) polyline.pop_back();
    // End tangent and curvature from the circle through three points 2·trim apart.
    const Vec2 e = polyline.back();
    const double span = std::max(2 * trim, 2.0);
    const Vec2 b = point_back_from(polyline, polyline.size() - 1, span);
    const Vec2 c = point_back_from(polyline, polyline.size() - 1, 2 * span);
    const Vec2 chord = e - b, previous = b - c;
    if (chord.norm() == 0) continue;
    double kappa = 0;
    if (previous.norm() > 0) {
      const double turn =
          std::atan2(previous.x() * chord.y() - previous.y() * chord.x(), previous.dot(chord));
      kappa = turn / (0.5 * (chord.norm() + previous.norm()));
    }
    const Vec2 d = rotate(chord.normalized(), 0.5 * kappa * chord.norm());
    // How far the samples reach beyond the end: the 98th percentile of their distance along
    // the tangent (a stray outlier near the line must not stretch the curve).
    std::vector<double> beyond;
    for (const Vec2& s : samples) {
      const Vec2 v = delta(e, s, period);
      const double t = v.dot(d);
      if (t > 0 && (v - t * d).norm() <= reach + 0.5 * std::abs(kappa) * t * t) beyond.push_back(t);
    }
    double tmax = 0;
    if (!beyond.empty()) {
      const size_t k = static_cast<size_t>(kEndQuantile * static_cast<double>(beyond.size()));
      std::nth_element(beyond.begin(), beyond.begin() + k, beyond.end());
      tmax = beyond[k];
    }
    // Follow the circle (turning at most 45°), in steps of one pixel.
    kappa = std::clamp(kappa, -kMaxTurn / std::max(tmax, 1.0), kMaxTurn / std::max(tmax, 1.0));
    Vec2 p = e;
    for (double t = 0; t < tmax;) {
      const double h = std::min(1.0, tmax - t);
      if (h < 0.5 && t > 0) break;
      p += h * rotate(d, kappa * (t + 0.5 * h));
      t += h;
      polyline.push_back(p);
    }
  }
}

}  // namespace qd::approximate
