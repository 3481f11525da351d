// An entry that moved keeps working under its old spelling (parameter_text.h,
// read_moved_entries): a wall's `Wear/Archard coefficient` of an older case file is read as
// `Wear/Archard/Coefficient`, where it is now, in the file and in --set, with a note naming
// where it was read; the last setting still wins whichever spelling gives it, and every later
// line of the file keeps its number in messages.
#include <abrade/coupling/parameters/earlier_printings.h>
#include <abrade/coupling/parameters/parameter_file.h>
#include <abrade/coupling/parameters/parameter_renames.h>
#include <abrade/coupling/parameters/parameter_text.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace
{
  namespace fs = std::filesystem;

  const std::string knife_bed = ABRADE_TESTS_DIR "/../cases/knife_bed/knife_bed.prm";

  /// The test's own directory (per process), removed when the test program ends.
  const fs::path &case_directory()
  {
    static const struct Directory
    {
      fs::path path = fs::temp_directory_path() / ("abrade_moved_entries_" + std::to_string(::getpid()));
      ~Directory()
      {
        std::error_code ignored;
        fs::remove_all(path, ignored);
      }
    } directory;
    return directory.path;
  }

  /// Writes @p body after an include of the knife-bed case into a file of its own.
  std::string case_file(const std::string &name, const std::string &body)
  {
    const fs::path &dir = case_directory();
    fs::create_directories(dir);
    const std::string file = (dir / name).string();
    std::ofstream(file) << "include " << knife_bed << "\n" << body;
    return file;
  }

  double coefficient(abrade::coupling::ParameterFile &f, const std::string &law)
  {
    auto &prm = f.handler();
    prm.enter_subsection("Wall knife");
    prm.enter_subsection("Wear");
    prm.enter_subsection(law);
    const double w = prm.get_double("Coefficient");
    prm.leave_subsection();
    prm.leave_subsection();
    prm.leave_subsection();
    return w;
  }

  /// The message of the error reading @p file with @p sets gives ("" when it is read).
  std::string refusal(const std::string &file, const std::vector<std::string> &sets = {})
  {
    try
      {
        abrade::coupling::ParameterFile f(file, sets);
      }
    catch (const std::exception &e)
      {
        return e.what();
      }
    return "";
  }

  std::string text_of(const std::string &file)
  {
    std::ostringstream text;
    text << std::ifstream(file).rdbuf();
    return text.str();
  }

  bool has_note(const abrade::coupling::ParameterFile &f, const std::string &text)
  {
    for (const auto &n : f.notes())
      if (n.find(text) != std::string::npos)
        return true;
    return false;
  }
} // namespace

TEST(MovedEntries, TheOldSpellingInAFileIsReadWhereTheEntryIsNow)
{
  const std::string file = case_file("old.prm", "subsection Wall knife\n"
                                                "  subsection Wear\n"
                                                "    set Laws = archard, finnie\n"
                                                "    set Archard coefficient = 3e-14   # an older file\n"
                                                "    set Finnie coefficient  = 0.25\n"
                                                "  end\n"
                                                "end\n");
  abrade::coupling::ParameterFile f(file, {});
  EXPECT_EQ(coefficient(f, "Archard"), 3e-14);
  EXPECT_EQ(coefficient(f, "Finnie"), 0.25);
  EXPECT_TRUE(has_note(f, file + ":5: Wall knife/Wear/Archard coefficient is read as Wall knife/Wear/Archard/Coefficient"));
  EXPECT_TRUE(has_note(f, file + ":6: Wall knife/Wear/Finnie coefficient is read as"));
}

TEST(MovedEntries, TheLastSettingWinsWhicheverSpellingGivesIt)
{
  const std::string new_last = case_file("new_last.prm", "subsection Wall knife\n  subsection Wear\n"
                                                         "    set Archard coefficient = 3e-14\n"
                                                         "    subsection Archard\n      set Coefficient = 5e-14\n    end\n"
                                                         "  end\nend\n");
  abrade::coupling::ParameterFile a(new_last, {});
  EXPECT_EQ(coefficient(a, "Archard"), 5e-14);
  const std::string old_last = case_file("old_last.prm", "subsection Wall knife\n  subsection Wear\n"
                                                         "    subsection Archard\n      set Coefficient = 5e-14\n    end\n"
                                                         "    set Archard coefficient = 3e-14\n"
                                                         "  end\nend\n");
  abrade::coupling::ParameterFile b(old_last, {});
  EXPECT_EQ(coefficient(b, "Archard"), 3e-14);
  // (the knife-bed case itself sets the new spelling to 1: the old one after it wins)
  abrade::coupling::ParameterFile c(knife_bed, {"Wall knife/Wear/Archard coefficient=7e-14"});
  EXPECT_EQ(coefficient(c, "Archard"), 7e-14);
  EXPECT_TRUE(has_note(c, "--set 'Wall knife/Wear/Archard coefficient=7e-14': Wall knife/Wear/Archard coefficient is "
                          "read as Wall knife/Wear/Archard/Coefficient"));
  abrade::coupling::ParameterFile d(knife_bed, {"Wall knife/Wear/Archard coefficient=7e-14",
                                                "Wall knife/Wear/Archard/Coefficient=2e-14"});
  EXPECT_EQ(coefficient(d, "Archard"), 2e-14);
}

// the rewritten entry takes three lines where it had one (or continued over several): a mistake
// after it is still named by its own line, and a continued value is read whole
TEST(MovedEntries, LaterLinesKeepTheirNumbers)
{
  const std::string file = case_file("numbers.prm", "subsection Wall knife\n"
                                                    "  subsection Wear\n"
                                                    "    set Archard coefficient = \\\n"
                                                    "        4e-14\n"
                                                    "    set Lawz = archard\n"
                                                    "  end\n"
                                                    "end\n");
  const std::string misspelt = refusal(file);
  EXPECT_NE(misspelt.find(file + ":6:"), std::string::npos) << misspelt;
  EXPECT_NE(misspelt.find("Lawz"), std::string::npos) << misspelt;
  const std::string whole = case_file("continued.prm", "subsection Wall knife\n"
                                                       "  subsection Wear\n"
                                                       "    set Archard coefficient = \\\n"
                                                       "        4e-14\n"
                                                       "  end\n"
                                                       "end\n");
  abrade::coupling::ParameterFile f(whole, {});
  EXPECT_EQ(coefficient(f, "Archard"), 4e-14);
  EXPECT_EQ(f.locate({"Wall knife", "Wear", "Archard"}, "Coefficient"), whole + ":4");
}

// a bad value given by the old spelling: the message names the line and says which entry it is
// (deal.II's names the new one)
TEST(MovedEntries, ABadValueUnderTheOldSpellingIsNamedAsWritten)
{
  const std::string file = case_file("bad.prm", "subsection Wall knife\n"
                                                "  subsection Wear\n"
                                                "    set Archard coefficient = -5e-14\n"
                                                "  end\n"
                                                "end\n");
  const std::string in_file = refusal(file);
  EXPECT_EQ(in_file.rfind(file + ":4:", 0), 0u) << in_file;
  EXPECT_NE(in_file.find("Wall knife/Wear/Archard coefficient is read as Wall knife/Wear/Archard/Coefficient"),
            std::string::npos)
    << in_file;
  const std::string in_set = refusal(knife_bed, {"Wall knife/Wear/Finnie coefficient=-1"});
  EXPECT_NE(in_set.find("--set 'Wall knife/Wear/Finnie coefficient=-1'"), std::string::npos) << in_set;
  EXPECT_NE(in_set.find("Finnie coefficient is read as"), std::string::npos) << in_set;
}

// the note goes only with the error of its own line or --set, also where the file's path or the
// --set's value holds ": " (the note's place is not found by searching its text)
TEST(MovedEntries, TheNoteGoesOnlyWithItsOwnError)
{
  const std::string file = case_file("run: 2.prm", "subsection Wall knife\n"
                                                   "  subsection Wear\n"
                                                   "    set Archard coefficient = 3e-14\n"
                                                   "    set Lawz = archard\n"
                                                   "  end\n"
                                                   "end\n");
  const std::string other = refusal(file);
  EXPECT_NE(other.find(file + ":5:"), std::string::npos) << other;
  EXPECT_EQ(other.find("is read as"), std::string::npos) << other;
  const std::string in_set = refusal(knife_bed, {"Wall knife/Wear/Archard coefficient=2e-14: x"});
  EXPECT_NE(in_set.find(" (Wall knife/Wear/Archard coefficient is read as Wall knife/Wear/Archard/Coefficient"),
            std::string::npos)
    << in_set;
}

namespace
{
  double part_length(abrade::coupling::ParameterFile &f)
  {
    auto &prm = f.handler();
    prm.enter_subsection("Part");
    const double l = prm.get_double("Length");
    prm.leave_subsection();
    return l;
  }
} // namespace

// subsection Knife, renamed Part (the part that wears need not be a knife), in a file and in a
// --set, with a note naming where it was read; the last setting wins whichever name gives it
TEST(MovedEntries, TheKnifeSubsectionIsReadAsThePart)
{
  const std::string old_name = case_file("knife.prm", "subsection Knife   # an older file\n"
                                                      "  set Length = 0.3\n"
                                                      "end\n");
  abrade::coupling::ParameterFile a(old_name, {});
  EXPECT_EQ(part_length(a), 0.3);
  EXPECT_TRUE(has_note(a, old_name + ":2: subsection Knife is read as subsection Part"));

  abrade::coupling::ParameterFile b(knife_bed, {"Knife/Length=0.25"});
  EXPECT_EQ(part_length(b), 0.25);
  EXPECT_TRUE(has_note(b, "--set 'Knife/Length=0.25': subsection Knife is read as subsection Part"));

  const std::string both = case_file("both.prm", "subsection Part\n  set Length = 0.2\nend\n"
                                                 "subsection Knife\n  set Length = 0.3\nend\n"
                                                 "subsection Part\n  set Height = 0.6\nend\n");
  abrade::coupling::ParameterFile c(both, {});
  EXPECT_EQ(part_length(c), 0.3);
  // a bad value under the old name is named by its file and line
  const std::string bad   = case_file("bad_length.prm", "subsection Knife\n  set Length = -1\nend\n");
  const std::string error = refusal(bad);
  EXPECT_EQ(error.rfind(bad + ":3:", 0), 0u) << error;
}

// `subsection Knife` continued over two lines is renamed whole; the lines after it keep their
// numbers in messages
TEST(MovedEntries, AContinuedKnifeSubsectionLineIsReadAsThePart)
{
  const std::string continued = case_file("continued_knife.prm", "subsection \\\n"
                                                                 "    Knife\n"
                                                                 "  set Length = 0.3\n"
                                                                 "end\n");
  abrade::coupling::ParameterFile a(continued, {});
  EXPECT_EQ(part_length(a), 0.3);
  EXPECT_TRUE(has_note(a, continued + ":2: subsection Knife is read as subsection Part"));
  const std::string bad   = case_file("continued_bad.prm", "subsection \\\n"
                                                           "    Knife\n"
                                                           "  set Height = 0.5\n"
                                                           "  set Length = -1\n"
                                                           "end\n");
  const std::string error = refusal(bad);
  EXPECT_EQ(error.rfind(bad + ":5:", 0), 0u) << error;
}

// Job = knife, renamed part (the job that builds the part alone), in a file and in a --set, with
// a note; printed with the old names, it is `knife` again
TEST(MovedEntries, TheKnifeJobIsReadAsThePartJob)
{
  const std::string old_job = case_file("knife_job.prm", "set Job = knife   # an older file\n");
  abrade::coupling::ParameterFile a(old_job, {});
  EXPECT_EQ(a.handler().get("Job"), "part");
  EXPECT_TRUE(has_note(a, old_job + ":2: Job = knife is read as Job = part"));
  abrade::coupling::ParameterFile b(knife_bed, {"Job=knife"});
  EXPECT_EQ(b.handler().get("Job"), "part");
  EXPECT_TRUE(has_note(b, "--set 'Job=knife': Job = knife is read as Job = part"));
  const std::string printed = b.canonical_text();
  EXPECT_NE(printed.find("set Job   = part\n"), std::string::npos) << printed.substr(0, 80);
  const auto earlier = abrade::coupling::earlier_printings(printed); // (layouts 4, 3, 2, 1, 0)
  ASSERT_EQ(earlier.size(), 5u);
  EXPECT_NE(earlier[0].find("set Job   = part\n"), std::string::npos);
  EXPECT_NE(earlier[1].find("set Job   = part\n"), std::string::npos);
  EXPECT_NE(earlier[2].find("set Job   = part\n"), std::string::npos);
  EXPECT_NE(earlier[3].find("set Job   = knife\n"), std::string::npos);
  EXPECT_NE(earlier[4].find("set Job   = knife\n"), std::string::npos);
  EXPECT_NE(printed.find("DEM from"), std::string::npos);
  EXPECT_EQ(earlier[0].find("DEM from"), std::string::npos);          // (added in layout 5)
  EXPECT_NE(earlier[0].find("Fine region pours"), std::string::npos);
  EXPECT_EQ(earlier[1].find("Fine region pours"), std::string::npos); // (added in layout 4)
  // another job is read as it is, without a note
  abrade::coupling::ParameterFile c(knife_bed, {"Job=dem"});
  EXPECT_EQ(c.handler().get("Job"), "dem");
  EXPECT_TRUE(c.notes().empty());
}

// a lifetime checkpoint hashes the printed parameters, and a run directory's parameters.prm is
// them: an earlier abrade printed them under its names, in its places and with the entries it
// had. printed_before_part_rename.prm is the parameters.prm an abrade before subsection Knife
// became Part wrote (cases/lifetime/small.prm, coarse-grained): read now and printed, it says
// Part, and as the earliest layout printed it, it is that file again, byte for byte
TEST(MovedEntries, TheParametersPrintedWithTheOldNamesAreWhatAnEarlierAbradePrinted)
{
  const std::string               file = ABRADE_TESTS_DIR "/unit/printed_before_part_rename.prm";
  abrade::coupling::ParameterFile f(file, {});
  const std::string               now = f.canonical_text();
  EXPECT_EQ(now.find("subsection Knife"), std::string::npos);
  EXPECT_NE(now.find("subsection Part"), std::string::npos);
  EXPECT_EQ(abrade::coupling::earlier_printings(now).back(), text_of(file));
}

// printed_before_wear_source_subsections.prm is the parameters.prm the abrade before the wear
// sources' subsections wrote (a run of the grab concepts test; its two directories made
// relative): the sources' entries flat in Lifetime, Knife mount and Knife protrusion, a fixed
// wall's velocity table (the knives' and the container's, empty). Read now and printed, it has
// none of them; as the layout before printed it, it is that file again, byte for byte. Each
// later layout undone alone is needed: without the velocity table put back, or the entries
// moved back, it differs.
TEST(MovedEntries, TheParametersAreWhatTheAbradeBeforeTheWearSourceSubsectionsPrinted)
{
  const std::string               file = ABRADE_TESTS_DIR "/unit/printed_before_wear_source_subsections.prm";
  abrade::coupling::ParameterFile f(file, {});
  const std::string               now = f.canonical_text();
  EXPECT_EQ(now.find("Analytic wear rate"), std::string::npos);
  EXPECT_EQ(now.find("Knife mount"), std::string::npos);
  EXPECT_NE(now.find("  subsection Analytic\n"), std::string::npos);
  EXPECT_NE(now.find("  set Mounted on          = left\n"), std::string::npos);
  const auto earlier = abrade::coupling::earlier_printings(now);
  // (the printings of layouts current - 1, ..., 0: layout 2's is at current - 3)
  EXPECT_EQ(earlier.at(abrade::coupling::renames::current_layout - 3), text_of(file));
  // ... and the same parameters printed now are the text itself again: none of the layouts
  // before reads as today's
  for (const auto &text : earlier)
    EXPECT_NE(text, now);
}

// each wear source's entries moved into its own subsection of Lifetime (the plugins own them):
// the old spellings of an older file and of --set are read there, with a note each
TEST(MovedEntries, AWearSourcesEntriesAreReadInItsSubsection)
{
  const std::string file = case_file("old_source.prm", "subsection Lifetime\n"
                                                       "  set Wear source = analytic\n"
                                                       "  set Analytic wear rate = 2e-6*(z < 0.01)   # an older file\n"
                                                       "  set Analytic wear is = volume\n"
                                                       "  set Replay run = elsewhere\n"
                                                       "end\n");
  abrade::coupling::ParameterFile f(file, {"Lifetime/Ranks per bed=2", "Lifetime/Analytic seed scatter=0.1"});
  auto &prm = f.handler();
  prm.enter_subsection("Lifetime");
  EXPECT_EQ(prm.get("Wear source"), "analytic");
  prm.enter_subsection("Analytic");
  EXPECT_EQ(prm.get("Wear rate"), "2e-6*(z < 0.01)");
  EXPECT_EQ(prm.get("Wear is"), "volume");
  EXPECT_EQ(prm.get_double("Seed scatter"), 0.1);
  prm.leave_subsection();
  prm.enter_subsection("Replay");
  EXPECT_EQ(prm.get("Run"), "elsewhere");
  prm.leave_subsection();
  prm.enter_subsection("DEM");
  EXPECT_EQ(prm.get_integer("Ranks per bed"), 2);
  prm.leave_subsection();
  prm.leave_subsection();
  EXPECT_TRUE(has_note(f, file + ":4: Lifetime/Analytic wear rate is read as Lifetime/Analytic/Wear rate"));
  EXPECT_TRUE(has_note(f, file + ":5: Lifetime/Analytic wear is is read as Lifetime/Analytic/Wear is"));
  EXPECT_TRUE(has_note(f, file + ":6: Lifetime/Replay run is read as Lifetime/Replay/Run"));
  EXPECT_TRUE(has_note(f, "--set 'Lifetime/Ranks per bed=2': Lifetime/Ranks per bed is read as "
                          "Lifetime/DEM/Ranks per bed"));
  EXPECT_TRUE(has_note(f, "--set 'Lifetime/Analytic seed scatter=0.1': Lifetime/Analytic seed scatter is read as "
                          "Lifetime/Analytic/Seed scatter"));
  // the old key where it never was is an unknown entry that says where it went
  const std::string elsewhere = refusal(case_file("misplaced.prm", "subsection Output\n"
                                                                   "  set Analytic wear rate = 1e-6\n"
                                                                   "end\n"));
  EXPECT_NE(elsewhere.find("'Analytic wear rate' moved: subsection Analytic, set Wear rate (inside Lifetime: each "
                           "wear source has its subsection)"),
            std::string::npos)
    << elsewhere;
}

// the solid model's mounting entries are named for any part (the part on a shell's lip need not
// be a knife): Knife mount and Knife protrusion of an older file or --set are read under their
// names now, in whichever wall they are
TEST(MovedEntries, TheMountingEntriesAreReadUnderTheirNamesNow)
{
  const std::string file = case_file("old_mount.prm", "subsection Wall knife\n"
                                                      "  set Geometry         = solid model\n"
                                                      "  set Knife mount      =        # an older file\n"
                                                      "  set Knife protrusion = 0.03\n"
                                                      "end\n");
  abrade::coupling::ParameterFile f(file, {});
  auto &prm = f.handler();
  prm.enter_subsection("Wall knife");
  EXPECT_EQ(prm.get_double("Protrusion"), 0.03);
  EXPECT_EQ(prm.get("Mounted on"), "");
  prm.leave_subsection();
  EXPECT_TRUE(has_note(f, file + ":4: Wall knife/Knife mount is read as Wall knife/Mounted on (its name now"));
  EXPECT_TRUE(has_note(f, file + ":5: Wall knife/Knife protrusion is read as Wall knife/Protrusion (its name now"));
  abrade::coupling::ParameterFile g(knife_bed, {"Wall knife/Geometry=solid model", "Wall knife/Knife protrusion=0.04"});
  g.handler().enter_subsection("Wall knife");
  EXPECT_EQ(g.handler().get_double("Protrusion"), 0.04);
  g.handler().leave_subsection();
  EXPECT_TRUE(has_note(g, "--set 'Wall knife/Knife protrusion=0.04': Wall knife/Knife protrusion is read as Wall "
                          "knife/Protrusion"));
  // outside a wall it is an unknown entry that says its name now
  const std::string elsewhere = refusal(case_file("misplaced_mount.prm", "subsection Part\n"
                                                                         "  set Knife protrusion = 0.03\n"
                                                                         "end\n"));
  EXPECT_NE(elsewhere.find("'Knife protrusion' is now 'Protrusion' (in subsection Wall NAME: the part mounted need "
                           "not be a knife)"),
            std::string::npos)
    << elsewhere;
}
