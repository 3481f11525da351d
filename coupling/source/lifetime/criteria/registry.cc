// The registry of end-of-life criteria (end_of_life_criterion.h): each criterion's file adds
// its factory with ABRADE_REGISTER_END_OF_LIFE_CRITERION before main() runs.
#include <abrade/coupling/lifetime/end_of_life_criterion.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace abrade::coupling::lifetime
{
  namespace
  {
    std::vector<EndOfLifeCriterionFactory> &factories()
    {
      static std::vector<EndOfLifeCriterionFactory> f;
      return f;
    }
  } // namespace

  EndOfLifeCriterionRegistration::EndOfLifeCriterionRegistration(EndOfLifeCriterionFactory make)
  {
    const std::string name = make()->name();
    for (const auto &other : factories())
      if (other()->name() == name)
        {
          std::fprintf(stderr, "abrade: the end-of-life criterion '%s' is registered twice\n", name.c_str());
          std::abort();
        }
    factories().push_back(make);
  }

  std::vector<std::unique_ptr<EndOfLifeCriterion>> make_end_of_life_criteria()
  {
    std::vector<std::unique_ptr<EndOfLifeCriterion>> all;
    for (const auto &make : factories())
      all.push_back(make());
    // (the order of registration is the linker's: by name, the same in every build)
    std::sort(all.begin(), all.end(), [](const auto &a, const auto &b) { return a->name() < b->name(); });
    return all;
  }

  void declare_end_of_life_criteria(dealii::ParameterHandler &prm)
  {
    for (const auto &c : make_end_of_life_criteria())
      c->declare_parameters(prm);
  }
} // namespace abrade::coupling::lifetime
