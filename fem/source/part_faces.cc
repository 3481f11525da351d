// Which faces of a part wear and which are held: the file's face numbers and the parameter
// file's selectors (part_faces.h).
#include <abrade/common/finite_number.h>
#include <abrade/fem/part_faces.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace abrade::fem
{
  using namespace dealii;

  namespace
  {
    std::string trim(const std::string &s)
    {
      const auto a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t");
      return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
    }

    std::vector<double> numbers(const std::string &text, const std::string &selector)
    {
      std::vector<double> v;
      for (const auto &x : Utilities::split_string_list(text, ','))
        {
          const auto d = io::finite_number(x);
          if (!d)
            throw std::invalid_argument("'" + selector + "': '" + x + "' is not a number");
          v.push_back(*d);
        }
      return v;
    }

    /// The outward normal (length: twice the area) of boundary face @p f of @p cell.
    Tensor<1, 3> outward_area_normal(const Triangulation<3>::active_cell_iterator &cell, unsigned f)
    {
      const auto   face = cell->face(f);
      Tensor<1, 3> n;
      if (face->n_vertices() == 3)
        n = cross_product_3d(face->vertex(1) - face->vertex(0), face->vertex(2) - face->vertex(0));
      else // a quadrilateral, vertices in lexicographic order: its diagonals
        n = cross_product_3d(face->vertex(3) - face->vertex(0), face->vertex(2) - face->vertex(1));
      if (n * (face->center() - cell->center()) < 0)
        n = -n;
      return n;
    }

    bool takes(const FaceSelector &s, types::boundary_id id, const std::map<types::boundary_id, std::string> &names,
               const Point<3> &centre, const Tensor<1, 3> &unit_normal)
    {
      switch (s.kind)
        {
          case FaceSelector::Kind::group:
            {
              // a name the file gives takes precedence over a number (a group named "7" is not
              // the group of tag 7)
              const bool is_a_name = std::any_of(names.begin(), names.end(),
                                                 [&](const auto &n) { return n.second == s.group; });
              if (is_a_name)
                {
                  const auto it = names.find(id);
                  return it != names.end() && it->second == s.group;
                }
              return s.group == std::to_string(id);
            }
          case FaceSelector::Kind::box:
            for (unsigned c = 0; c < 3; ++c)
              if (centre[c] < s.box[c] || centre[c] > s.box[c + 3])
                return false;
            return true;
          case FaceSelector::Kind::normal:
            {
              const Tensor<1, 3> d({s.direction[0], s.direction[1], s.direction[2]});
              return unit_normal * d >= std::cos(s.angle_degrees * M_PI / 180) - 1e-12;
            }
          case FaceSelector::Kind::cylinder:
            {
              // the centre's distance from the axis, and the normal across it (a facet of a
              // bore or a pin: radial, inwards or outwards)
              const Tensor<1, 3> a({s.direction[0], s.direction[1], s.direction[2]});
              Tensor<1, 3>       d = centre - Point<3>(s.box[0], s.box[1], s.box[2]);
              d -= (d * a) * a;
              return std::abs(d.norm() - s.radius) <= s.tolerance &&
                     std::abs(unit_normal * a) <= std::sin(15 * M_PI / 180);
            }
        }
      return false;
    }
  } // namespace

  std::vector<FaceSelector> parse_face_selectors(const std::string &text)
  {
    std::vector<FaceSelector> out;
    for (const auto &item : Utilities::split_string_list(text, ';'))
      {
        const std::string s     = trim(item);
        const auto        space = s.find_first_of(" \t");
        const std::string kind  = s.substr(0, space);
        const std::string rest  = space == std::string::npos ? std::string() : trim(s.substr(space));
        FaceSelector      f;
        f.text = s;
        if (kind == "group")
          {
            if (rest.empty())
              throw std::invalid_argument("'" + s + "': a group needs a name or a number");
            f.kind = FaceSelector::Kind::group, f.group = rest;
          }
        else if (kind == "box")
          {
            const auto v = numbers(rest, s);
            if (v.size() != 6)
              throw std::invalid_argument("'" + s + "': a box needs six numbers 'x0, y0, z0, x1, y1, z1'");
            f.kind = FaceSelector::Kind::box;
            for (unsigned c = 0; c < 3; ++c)
              {
                f.box[c] = std::min(v[c], v[c + 3]), f.box[c + 3] = std::max(v[c], v[c + 3]);
              }
          }
        else if (kind == "normal")
          {
            const auto v = numbers(rest, s);
            if (v.size() != 3 && v.size() != 4)
              throw std::invalid_argument("'" + s + "': a normal needs 'nx, ny, nz' or 'nx, ny, nz, angle'");
            const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            if (!(length > 0))
              throw std::invalid_argument("'" + s + "': the direction must not be zero");
            f.kind = FaceSelector::Kind::normal;
            for (unsigned c = 0; c < 3; ++c)
              f.direction[c] = v[c] / length;
            if (v.size() == 4)
              {
                if (!(v[3] >= 0 && v[3] <= 180))
                  throw std::invalid_argument("'" + s + "': the angle is in degrees, 0 to 180");
                f.angle_degrees = v[3];
              }
          }
        else if (kind == "cylinder")
          {
            const auto v = numbers(rest, s);
            if (v.size() != 7 && v.size() != 8)
              throw std::invalid_argument("'" + s + "': a cylinder needs 'px, py, pz, ax, ay, az, radius' or "
                                          "'px, py, pz, ax, ay, az, radius, tolerance' (a point of its axis, the "
                                          "axis' direction, its radius in metres)");
            const double length = std::sqrt(v[3] * v[3] + v[4] * v[4] + v[5] * v[5]);
            if (!(length > 0))
              throw std::invalid_argument("'" + s + "': the axis' direction must not be zero");
            if (!(v[6] > 0))
              throw std::invalid_argument("'" + s + "': the radius must be positive");
            f.kind = FaceSelector::Kind::cylinder;
            for (unsigned c = 0; c < 3; ++c)
              f.box[c] = v[c], f.direction[c] = v[3 + c] / length;
            f.radius    = v[6];
            f.tolerance = v.size() == 8 ? v[7] : 0.15 * v[6];
            if (!(f.tolerance > 0))
              throw std::invalid_argument("'" + s + "': the tolerance must be positive");
          }
        else
          throw std::invalid_argument("'" + s + "': a selector is 'group NAME', 'box x0, y0, z0, x1, y1, z1', "
                                      "'normal nx, ny, nz[, angle]' or 'cylinder px, py, pz, ax, ay, az, radius[, "
                                      "tolerance]'");
        out.push_back(f);
      }
    return out;
  }

  std::vector<PartFace> part_faces(const Triangulation<3> &tria, const std::map<types::boundary_id, std::string> &names)
  {
    std::map<types::boundary_id, PartFace> faces;
    for (const auto &cell : tria.active_cell_iterators())
      for (const unsigned f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            const types::boundary_id id = cell->face(f)->boundary_id();
            PartFace                &p  = faces[id];
            const Tensor<1, 3>       n  = outward_area_normal(cell, f);
            const double             a  = 0.5 * n.norm();
            p.id = id;
            p.area += a;
            p.centre += a * cell->face(f)->center();
            p.normal += 0.5 * n;
          }
    std::vector<PartFace> out;
    for (auto &[id, p] : faces)
      {
        if (p.area > 0)
          p.centre /= p.area;
        // a closed face (a bolt hole's cylinder) has no mean direction
        p.normal = p.normal.norm() > 1e-6 * p.area ? p.normal / p.normal.norm() : Tensor<1, 3>();
        if (const auto it = names.find(id); it != names.end())
          p.name = it->second;
        out.push_back(p);
      }
    return out;
  }

  FaceAssignment assign_faces(Triangulation<3> &tria, const std::vector<FaceSelector> &clamped,
                              const std::vector<FaceSelector> &wearable, const std::map<types::boundary_id, std::string> &names,
                              types::boundary_id wearable_id, types::boundary_id clamped_id)
  {
    std::vector<unsigned> clamped_hits(clamped.size(), 0), wearable_hits(wearable.size(), 0);
    FaceAssignment        r;
    for (const auto &c : clamped)
      r.taken.push_back({"Clamped faces", c.text, 0.0, {}});
    for (const auto &w : wearable)
      r.taken.push_back({"Wearable faces", w.text, 0.0, {}});
    auto took = [&](std::size_t k, types::boundary_id id, double area) {
      auto &t = r.taken[k];
      t.area += area;
      if (std::find(t.faces.begin(), t.faces.end(), id) == t.faces.end())
        t.faces.push_back(id);
    };
    for (const auto &cell : tria.active_cell_iterators())
      for (const unsigned f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            const types::boundary_id id = cell->face(f)->boundary_id();
            const Tensor<1, 3>       n  = outward_area_normal(cell, f);
            const Point<3>           c  = cell->face(f)->center();
            const Tensor<1, 3>       u  = n.norm() > 0 ? n / n.norm() : n;
            const double             area       = 0.5 * n.norm();
            bool                     is_clamped = false, wears = wearable.empty();
            for (std::size_t k = 0; k < clamped.size(); ++k)
              if (takes(clamped[k], id, names, c, u))
                is_clamped = true, ++clamped_hits[k], took(k, id, area);
            for (std::size_t k = 0; k < wearable.size(); ++k)
              if (takes(wearable[k], id, names, c, u))
                wears = true, ++wearable_hits[k], took(clamped.size() + k, id, area);
            const bool w = wears && !is_clamped;
            cell->face(f)->set_boundary_id(w ? wearable_id : clamped_id);
            (w ? r.wearable_area : r.clamped_area) += area;
            ++(w ? r.wearable_faces : r.clamped_faces);
            r.boundary_faces.emplace_back(id, w            ? FaceAssignment::Became::wears
                                              : is_clamped ? FaceAssignment::Became::clamped
                                                           : FaceAssignment::Became::held);
            FaceAssignment::Role &role = r.by_face[id];
            (w ? role.wearing_area : is_clamped ? role.clamped_area : role.held_area) += area;
          }
    auto check = [](const std::vector<FaceSelector> &list, const std::vector<unsigned> &hits, const char *which) {
      for (std::size_t k = 0; k < list.size(); ++k)
        if (hits[k] == 0)
          throw std::invalid_argument(std::string(which) + " '" + list[k].text +
                                      "' takes no face of the part (boxes are in metres, in the part's frame after "
                                      "its scale and placement; the part job lists the faces)");
    };
    for (auto &t : r.taken)
      std::sort(t.faces.begin(), t.faces.end());
    check(clamped, clamped_hits, "Clamped faces:");
    check(wearable, wearable_hits, "Wearable faces:");
    if (r.wearable_faces == 0)
      throw std::invalid_argument("no face of the part wears (Clamped faces / Wearable faces take them all)");
    return r;
  }
} // namespace abrade::fem
