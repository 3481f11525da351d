// Gmsh without FLTK's preference files. libgmsh is built with its FLTK user interface, and
// gmsh::initialize() sets the "tooltips" option through Fl::option(), whose first call reads
// FLTK's preference files and writes them back (/etc/fltk/fltk.org/fltk.prefs and
// ~/.fltk/fltk.org/fltk.prefs, created if absent): two writes outside the run's output directory
// on every Gmsh session, which no Gmsh option or configuration-file flag turns off (the call
// is made by Gmsh's option defaults, before any option can be set).
//
// abrade never opens a window, so FLTK's options mean nothing to it: the two Fl::option
// functions are defined here, in the executables, where the dynamic linker finds them before
// FLTK's own (ELF symbol interposition), as no-ops. They are named by their mangled names since
// FLTK's headers are not installed (only its run-time library, as libgmsh's dependency). This
// file is linked into `abrade` and `abrade-mesher` only, never into a library; the strace
// check of cli/output_directory shows that a part job opens no preference file for writing.
extern "C"
{
  /// static bool Fl::option(Fl::Fl_Option): every option off
  __attribute__((visibility("default"), used)) bool abrade_fltk_option_get(int) __asm__("_ZN2Fl6optionENS_9Fl_OptionE");
  bool abrade_fltk_option_get(int) { return false; }

  /// static void Fl::option(Fl::Fl_Option, bool): ignored
  __attribute__((visibility("default"), used)) void abrade_fltk_option_set(int, bool) __asm__("_ZN2Fl6optionENS_9Fl_OptionEb");
  void abrade_fltk_option_set(int, bool) {}
}
