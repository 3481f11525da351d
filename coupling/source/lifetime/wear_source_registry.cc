// The registry of wear sources (Lifetime/Wear source, wear_source.h): each source's file adds its
// factory with ABRADE_REGISTER_WEAR_SOURCE before main() runs.
#include <abrade/coupling/lifetime/wear_source.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace abrade::coupling::lifetime
{
  namespace
  {
    std::vector<WearSourceFactory> &factories()
    {
      static std::vector<WearSourceFactory> f;
      return f;
    }

    /// The default of Lifetime/Wear source.
    const std::string default_source = "dem";
  } // namespace

  WearSourceRegistration::WearSourceRegistration(WearSourceFactory make)
  {
    const std::string name = make()->name();
    for (const auto &other : factories())
      if (other()->name() == name)
        {
          std::fprintf(stderr, "abrade: the wear source '%s' is registered twice\n", name.c_str());
          std::abort();
        }
    factories().push_back(make);
  }

  std::vector<std::unique_ptr<WearSourceChoice>> make_wear_source_choices()
  {
    std::vector<std::unique_ptr<WearSourceChoice>> all;
    for (const auto &make : factories())
      all.push_back(make());
    // (the order of registration is the linker's: by name, the same in every build)
    std::sort(all.begin(), all.end(), [](const auto &a, const auto &b) { return a->name() < b->name(); });
    return all;
  }

  std::unique_ptr<WearSourceChoice> make_wear_source_choice(const std::string &name)
  {
    for (const auto &make : factories())
      if (auto c = make(); c->name() == name)
        return c;
    return nullptr;
  }

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
      c->declare_parameters(prm);
  }
} // namespace abrade::coupling::lifetime
