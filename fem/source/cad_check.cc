// A STEP or IGES file checked by OpenCASCADE's own reader before Gmsh imports it (cad_check.h).
#include <abrade/common/error.h>
#include <abrade/common/file_extension.h>
#include <abrade/common/format_number.h>
#include <abrade/fem/cad_check.h>

#include <BRepBndLib.hxx>
#include <Bnd_Box.hxx>
#include <IGESControl_Reader.hxx>
#include <Interface_Check.hxx>
#include <Interface_CheckIterator.hxx>
#include <Interface_CheckTool.hxx>
#include <Interface_InterfaceModel.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <STEPControl_Reader.hxx>
#include <TCollection_HAsciiString.hxx>

#include <algorithm>
#include <cmath>
#include <cctype>
#include <memory>

namespace abrade::fem
{
  void check_cad_file(const std::string &path)
  {
    const std::string ext = io::lower_extension(path);
    // OpenCASCADE's reports go to its messenger's printers (the terminal): silenced here, the
    // error below says what matters
    const Handle(Message_Messenger) messenger = Message::DefaultMessenger();
    const Message_SequenceOfPrinters printers  = messenger->Printers();
    messenger->RemovePrinters(STANDARD_TYPE(Message_Printer));
    struct Restore
    {
      const Handle(Message_Messenger) &m;
      const Message_SequenceOfPrinters &p;
      ~Restore()
      {
        for (const auto &printer : p)
          m->AddPrinter(printer);
      }
    } restore{messenger, printers};

    std::unique_ptr<XSControl_Reader> reader;
    if (ext == ".step" || ext == ".stp")
      reader = std::make_unique<STEPControl_Reader>();
    else if (ext == ".iges" || ext == ".igs")
      reader = std::make_unique<IGESControl_Reader>();
    else
      return;
    if (reader->ReadFile(path.c_str()) != IFSelect_RetDone || reader->Model().IsNull())
      throw InputError(path, "OpenCASCADE cannot read it as a " + std::string(ext == ".igs" || ext == ".iges" ? "IGES" : "STEP") +
                               " file (cut short, or not one)");
    const Handle(Interface_InterfaceModel) model = reader->Model();
    Interface_CheckTool                    tool(model);
    Interface_CheckIterator                checks = tool.CompleteCheckList();
    long                                   failed = 0;
    std::string                            first;
    for (checks.Start(); checks.More(); checks.Next())
      if (checks.Value()->HasFailed())
        {
          if (failed++ == 0)
            {
              const Handle(Standard_Transient) entity = checks.Value()->Entity();
              std::string label = checks.Number() > 0 ? "entity " + std::to_string(checks.Number()) + ": " : "";
              if (!entity.IsNull() && !model->StringLabel(entity).IsNull())
                label = "entity " + std::string(model->StringLabel(entity)->ToCString()) + ": ";
              first = label + checks.Value()->Fail(1)->ToCString(); // (0: the file's syntax, with its line)
            }
        }
    if (failed > 0)
      throw InputError(path, std::to_string(failed) + " entit" + (failed == 1 ? "y" : "ies") +
                               " failed to read (" + first +
                               "); the file is damaged or uses what OpenCASCADE does not read: export it again");
    // coordinates of 1e18 or 1e30 make Gmsh's search trees assert (abort) or loop: the shapes'
    // bounding box, in millimetres (OpenCASCADE's unit), must be that of a part
    reader->TransferRoots();
    Bnd_Box box;
    BRepBndLib::Add(reader->OneShape(), box);
    if (!box.IsVoid())
      {
        double x0, y0, z0, x1, y1, z1;
        box.Get(x0, y0, z0, x1, y1, z1);
        const double largest = std::max({std::abs(x0), std::abs(y0), std::abs(z0), std::abs(x1), std::abs(y1), std::abs(z1)});
        if (!std::isfinite(largest) || largest > 1e7)
          throw InputError(path, "coordinates up to " + io::format_number(largest) +
                                   " mm (more than 10 km): a damaged file, or one in other units");
      }
  }
} // namespace abrade::fem
