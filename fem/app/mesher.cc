// abrade-mesher: the child process that makes Gmsh's volume meshes for abrade
// (fem/meshing_job.h), so that a crash or a hang inside Gmsh cannot take a run down.
#include <abrade/fem/meshing_job.h>

int main(int argc, char **argv) { return abrade::fem::meshing_job_main(argc, argv); }
