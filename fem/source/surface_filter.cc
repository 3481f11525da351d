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

      explicit EdgeGraph(const SolidSurface &s)
      {
        std::vector<std::vector<unsigned>> adj(s.vertices.size());
        for (const auto &t : s.triangles)
          for (int e = 0; e < 3; ++e)
            adj[t[e]].push_back(t[(e + 1) % 3]), adj[t[(e + 1) % 3]].push_back(t[e]);
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

  std::vector<std::pair<unsigned, double>> geodesic_neighbourhood(const SolidSurface &s, unsigned source, double cutoff)
  {
    const EdgeGraph     g(s);
    std::vector<double> distance(s.vertices.size(), std::numeric_limits<double>::infinity());
    return dijkstra(g, s.vertices.size(), source, cutoff, distance);
  }

  std::vector<double> filter_on_surface(const SolidSurface &s, const std::vector<double> &volume, double radius)
  {
    if (radius <= 0)
      return volume;
    const std::size_t   n = s.vertices.size();
    const EdgeGraph     g(s);
    const auto          area = vertex_areas(s);
    std::vector<double> distance(n, std::numeric_limits<double>::infinity());
    std::vector<double> out(n, 0.0);
    for (unsigned u = 0; u < n; ++u)
      {
        if (volume[u] == 0)
          continue;
        const auto reached = dijkstra(g, n, u, 3 * radius, distance);
        double     sum     = 0;
        std::vector<double> w(reached.size());
        for (std::size_t k = 0; k < reached.size(); ++k)
          {
            const double d = reached[k].second;
            w[k] = std::exp(-0.5 * d * d / (radius * radius)) * area[reached[k].first];
            sum += w[k];
          }
        if (!(sum > 0)) // an isolated vertex keeps its volume
          {
            out[u] += volume[u];
            continue;
          }
        for (std::size_t k = 0; k < reached.size(); ++k)
          out[reached[k].first] += volume[u] * w[k] / sum;
      }
    return out;
  }
} // namespace abrade::fem
