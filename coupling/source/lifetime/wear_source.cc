// The registry of wear sources (Lifetime/Wear source, wear_source.h): each source's file adds its
// factory with ABRADE_REGISTER_WEAR_SOURCE before main() runs; each declares its entries in its
// own subsection of Lifetime.
#include <abrade/coupling/lifetime/wear_source.h>

#include <algorithm>

namespace abrade::coupling::lifetime
{
  using Registry = io::PluginRegistry<WearSourceChoice>;

  namespace
  {

    /// The default of Lifetime/Wear source.
    const std::string default_source = "dem";
  } // namespace

  WearSourceRegistration::WearSourceRegistration(WearSourceFactory make) { Registry::add(make, "wear source"); }

  std::vector<std::unique_ptr<WearSourceChoice>> make_wear_source_choices() { return Registry::make_all(); }

  std::unique_ptr<WearSourceChoice> make_wear_source_choice(const std::string &name) { return Registry::make(name); }

  void declare_wear_sources(dealii::ParameterHandler &prm)
  {
    // the documentation: the default first, then the others by name
    auto        all = make_wear_source_choices();
    std::string names, doc;
    std::stable_partition(all.begin(), all.end(), [](const auto &c) { return c->name() == default_source; });
    for (const auto &c : all)
      {
        names += (names.empty() ? "" : "|") + c->name();
        doc += (doc.empty() ? "" : "; ") + c->name() + ": " + c->documentation();
      }
    prm.declare_entry("Wear source", default_source, dealii::Patterns::Selection(names), doc + ".");
    for (const auto &c : all)
      {
        prm.enter_subsection(c->section());
        c->declare_parameters(prm);
        prm.leave_subsection();
      }
  }
} // namespace abrade::coupling::lifetime
