#pragma once
// The registry every plugin family shares (end-of-life criteria, wall motions, wear sources):
// each plugin's file adds its factory with one line before main() runs, and the registry makes
// new instances, all of them in the order of their names (the order of registration is the
// linker's) or one by name. Header only: one registry per Base in a program.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

namespace abrade::io
{
  template <class Base>
  class PluginRegistry
  {
  public:
    using Factory = std::unique_ptr<Base> (*)();

    /// Adds @p make; a name registered twice is a bug (said, and the program stops). @p family
    /// names the plugins in that message ("wall motion").
    static void add(Factory make, const char *family)
    {
      const std::string name = make()->name();
      for (const auto &other : factories())
        if (other()->name() == name)
          {
            std::fprintf(stderr, "abrade: the %s '%s' is registered twice\n", family, name.c_str());
            std::abort();
          }
      factories().push_back(make);
    }

    /// One new instance of every registered plugin, in the order of their names.
    static std::vector<std::unique_ptr<Base>> make_all()
    {
      std::vector<std::unique_ptr<Base>> all;
      for (const auto &make : factories())
        all.push_back(make());
      std::sort(all.begin(), all.end(), [](const auto &a, const auto &b) { return a->name() < b->name(); });
      return all;
    }

    /// A new instance of the plugin of that name; nullptr if there is none.
    static std::unique_ptr<Base> make(const std::string &name)
    {
      for (const auto &f : factories())
        if (auto p = f(); p->name() == name)
          return p;
      return nullptr;
    }

  private:
    static std::vector<Factory> &factories()
    {
      static std::vector<Factory> f;
      return f;
    }
  };
} // namespace abrade::io

#define ABRADE_PLUGIN_CAT2(a, b) a##b
#define ABRADE_PLUGIN_CAT(a, b) ABRADE_PLUGIN_CAT2(a, b)
/// Registers @p Class with @p Registration (a type whose constructor takes the factory), at
/// namespace scope: what the families' ABRADE_REGISTER_* lines expand to.
#define ABRADE_REGISTER_PLUGIN(Registration, Base, Class)                                                  \
  static const Registration ABRADE_PLUGIN_CAT(abrade_plugin_, __LINE__)(                                   \
    []() -> std::unique_ptr<Base> { return std::make_unique<Class>(); })
