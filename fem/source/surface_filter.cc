// The wear filter: a per-vertex wear volume smoothed over the part's surface, volume
// conserving (surface_filter.h).
#include <abrade/fem/surface_filter.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>

namespace abrade::fem
{
  std::vector<double> vertex_areas(const SolidSurface &s, int only)
  {
    std::vector<double> a(s.vertices.size(), 0.0);
    for (std::size_t t = 0; t < s.triangles.size(); ++t)
      if (only < 0 || s.boundary_id[t] == dealii::types::boundary_id(only))
        for (unsigned v : s.triangles[t])
          a[v] += s.triangle_area(t) / 3;
    return a;
  }

  namespace
  {
    /// The surface's edges as a graph: neighbours of each vertex with the edge length (CSR).
    struct EdgeGraph
    {
      std::vector<unsigned> offset, neighbour;
      std::vector<double>   length;

      EdgeGraph(const SolidSurface &s, int only)
      {
        std::vector<std::vector<unsigned>> adj(s.vertices.size());
        for (std::size_t k = 0; k < s.triangles.size(); ++k)
          if (only < 0 || s.boundary_id[k] == dealii::types::boundary_id(only))
            for (int e = 0; e < 3; ++e)
              {
                const auto &t = s.triangles[k];
                adj[t[e]].push_back(t[(e + 1) % 3]), adj[t[(e + 1) % 3]].push_back(t[e]);
              }
        offset.push_back(0);
        for (std::size_t v = 0; v < adj.size(); ++v)
          {
            std::sort(adj[v].begin(), adj[v].end());
            adj[v].erase(std::unique(adj[v].begin(), adj[v].end()), adj[v].end());
            for (unsigned w : adj[v])
              neighbour.push_back(w), length.push_back(s.vertices[v].distance(s.vertices[w]));
            offset.push_back(unsigned(neighbour.size()));
          }
      }
    };

    std::vector<std::pair<unsigned, double>> dijkstra(const EdgeGraph &g, std::size_t n, unsigned source, double cutoff,
                                                      std::vector<double> &distance)
    {
      // distance: scratch of size n, all infinity on entry and on return
      using Item = std::pair<double, unsigned>;
      std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
      std::vector<std::pair<unsigned, double>>                          reached;
      distance[source] = 0;
      queue.push({0.0, source});
      while (!queue.empty())
        {
          const auto [d, v] = queue.top();
          queue.pop();
          if (d > distance[v])
            continue;
          reached.emplace_back(v, d);
          for (unsigned k = g.offset[v]; k < g.offset[v + 1]; ++k)
            {
              const unsigned w  = g.neighbour[k];
              const double   dw = d + g.length[k];
              if (dw < cutoff && dw < distance[w])
                distance[w] = dw, queue.push({dw, w});
            }
        }
      for (const auto &[v, d] : reached)
        distance[v] = std::numeric_limits<double>::infinity();
      (void)n;
      return reached;
    }
  } // namespace

  std::vector<std::pair<unsigned, double>> geodesic_neighbourhood(const SolidSurface &s, unsigned source, double cutoff,
                                                                  int only)
  {
    const EdgeGraph     g(s, only);
    std::vector<double> distance(s.vertices.size(), std::numeric_limits<double>::infinity());
    return dijkstra(g, s.vertices.size(), source, cutoff, distance);
  }

  std::vector<double> filter_on_surface(const SolidSurface &s, const std::vector<double> &volume, double radius,
                                        int only)
  {
    const std::size_t   n    = s.vertices.size();
    const auto          area = vertex_areas(s, only);
    std::vector<double> out(n, 0.0);
    double              total_in = 0;
    for (std::size_t v = 0; v < n; ++v)
      if (area[v] > 0)
        total_in += volume[v], out[v] = volume[v];
    if (radius <= 0)
      return out;
    // depth_v = sum_u G_uv V_u / sum_u G_uv A_u (G symmetric: one search from the receiver)
    const EdgeGraph     g(s, only);
    std::vector<double> distance(n, std::numeric_limits<double>::infinity());
    double              total_out = 0;
    for (unsigned v = 0; v < n; ++v)
      {
        out[v] = 0;
        if (!(area[v] > 0))
          continue;
        double num = 0, den = 0;
        for (const auto &[u, d] : dijkstra(g, n, v, 3 * radius, distance))
          {
            const double w = std::exp(-0.5 * d * d / (radius * radius));
            num += w * volume[u], den += w * area[u];
          }
        out[v] = den > 0 ? area[v] * num / den : 0.0;
        total_out += out[v];
      }
    // conserve the volume: one factor for the whole surface
    if (total_out > 0)
      for (double &x : out)
        x *= total_in / total_out;
    return out;
  }
} // namespace abrade::fem
