// Geometry = file: a surface mesh (STL, OBJ, PLY, VTK, VTP) or a CAD file whose surfaces Gmsh
// meshes, optionally with a lip a part can be mounted on (wall_geometry.h).
#include <abrade/dem/parameter_section.h>
#include <abrade/common/error.h>
#include <abrade/coupling/parameters/part_parameters.h>
#include <abrade/coupling/walls/wall_geometry.h>
#include <abrade/dem/mesh_io.h>
#include <abrade/fem/solid_file.h>

#include <limits>

namespace abrade::coupling
{
  namespace
  {
    dem::Vec3 vec(const std::array<double, 3> &v) { return dem::Vec3(v[0], v[1], v[2]); }

    class File : public WallGeometry
    {
    public:
      std::string name() const override { return "file"; }
      std::string documentation() const override { return "a surface mesh"; }

      void declare_parameters(dem::ParameterSection &prm) const override
      {
        prm.declare_text("File", "",
                         "Surface mesh file (STL ASCII/binary, OBJ, PLY, VTK, VTP) or CAD file "
                         "(STEP/IGES: its surfaces meshed by Gmsh to 'Maximum edge length') when "
                         "Geometry = file; relative to the parameter file's directory.");
        prm.declare_number("File scale", 1, 1e-12, dem::unbounded, "[m per file unit] 0.001 for a mesh in millimetres. Range: > 0.");
        prm.declare_numbers("Lip centre", "", 0, 3, -dem::unbounded, dem::unbounded,
                            "[m] A shell read from a file (Geometry = file) that carries a knife: the "
                            "centre of its lip, in the file's coordinates in metres (after File scale, before "
                            "Rotation and Offset): 'x, y, z'. "
                            "Empty: the wall has no lip.");
        prm.declare_vector("Lip direction", {0, 1, 0},
                           "Shell from a file: the direction along its lip. Its sign decides which face of "
                           "a mounted knife faces the material: the knife's inner face looks along "
                           "'Lip inward' x 'Lip direction', which should point into the shell.");
        prm.declare_vector("Lip inward", {0, 0, 1},
                           "Shell from a file: the direction from the lip into the shell along its bottom "
                           "(the mounted knife's height runs this way).");
      }

      WallShape make(const dem::ParameterSection &prm, const WallGeometryContext &context) const override
      {
        WallShape         shape;
        const std::string file = context.path_beside(prm.text("File"));
        if (file.empty())
          prm.fail("File", "Geometry = file needs a mesh file");
        shape.input_files.push_back(file);
        const double scale = prm.number("File scale"), h = context.maximum_edge_length;
        // CAD (a shell from a design tool): Gmsh meshes its surfaces to triangles of the wall's
        // 'Maximum edge length'
        const bool cad = fem::is_cad_file(file);
        if (cad && !(h > 0))
          prm.fail("Maximum edge length", "a CAD file (" + file + ") is meshed to this size: give a positive length");
        try
          {
            shape.mesh = cad ? wall_mesh(fem::read_cad_surface(file, h / scale), scale * Eigen::Matrix3d::Identity(),
                                         dem::Vec3::Zero())
                             : dem::read_surface_mesh(file, scale);
          }
        catch (const InputError &e)
          {
            prm.fail("File", e.what());
          }
        shape.lip = lip(prm);
        return shape;
      }

    private:
      /// The lip of Lip centre, Lip direction and Lip inward (none when Lip centre is empty).
      static std::optional<WallLip> lip(const dem::ParameterSection &prm)
      {
        const auto centre = prm.numbers("Lip centre");
        if (centre.empty())
          return std::nullopt;
        if (centre.size() != 3)
          prm.fail("Lip centre", "needs three numbers 'x, y, z' (or nothing)");
        const dem::Vec3 along = vec(prm.vector("Lip direction"));
        dem::Vec3       in    = vec(prm.vector("Lip inward"));
        if (!(along.norm() > 0))
          prm.fail("Lip direction", "must not be zero");
        in -= in.dot(along.normalized()) * along.normalized(); // square to the lip
        if (!(in.norm() > 1e-9 * along.norm()))
          prm.fail("Lip inward", "must not be parallel to 'Lip direction'");
        return WallLip{dem::Vec3(centre[0], centre[1], centre[2]), along.normalized(), in.normalized()};
      }
    };
  } // namespace

  ABRADE_REGISTER_WALL_GEOMETRY(File);
} // namespace abrade::coupling
