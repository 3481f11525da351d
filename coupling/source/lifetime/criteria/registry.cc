// The registry of end-of-life criteria (end_of_life_criterion.h): each criterion's file adds
// its factory with ABRADE_REGISTER_END_OF_LIFE_CRITERION before main() runs.
#include <abrade/coupling/lifetime/end_of_life_criterion.h>

#include <cstdio>
#include <cstdlib>

namespace abrade::coupling::lifetime
{
  using Registry = io::PluginRegistry<EndOfLifeCriterion>;

  // A name is lower-case words (the checkpoint keeps a criterion's entries under it, blanks as
  // '_': "history_maximum_depth"), not "tonnes" (history_tonnes is the trajectory's); names and
  // parameters are each registered once.
  EndOfLifeCriterionRegistration::EndOfLifeCriterionRegistration(EndOfLifeCriterionFactory make)
  {
    const auto  made  = make();
    const auto  name  = made->name();
    auto        wrong = [&](const char *why) {
      std::fprintf(stderr, "abrade: the end-of-life criterion '%s' %s\n", name.c_str(), why);
      std::abort();
    };
    if (name.empty() || name == "tonnes" ||
        name.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789 ") != std::string::npos)
      wrong("is not a name of lower-case words (nor 'tonnes')");
    for (const auto &other : Registry::make_all())
      if (other->parameter() == made->parameter())
        wrong("declares the parameter of another criterion");
    Registry::add(make, "end-of-life criterion");
  }

  std::vector<std::unique_ptr<EndOfLifeCriterion>> make_end_of_life_criteria() { return Registry::make_all(); }

  void declare_end_of_life_criteria(dealii::ParameterHandler &prm)
  {
    for (const auto &c : make_end_of_life_criteria())
      c->declare_parameters(prm);
  }
} // namespace abrade::coupling::lifetime
