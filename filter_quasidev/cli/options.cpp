// CLI11 parses the command line's shape (subcommands, options anywhere, --opt=value, --,
// repeated options, help); each value is converted by the subcommand's options
// (subcommand_options.cpp, declared_options.h), so every message keeps the command's wording:
// the option, the bad value and what to do.
#include "options.h"

#include <CLI/CLI.hpp>
#include <algorithm>

#include "option_values.h"
#include "subcommand_options.h"

namespace qd::cli {

namespace {

// --help and --version, which every level of the command has; the footer is inherited.
void add_help_and_version(CLI::App& app) {
  app.set_help_flag("-h,--help", "print this help and exit");
  app.set_version_flag("--version", std::string("quasidev ") + QD_VERSION,
                       "print the version and exit");
}

// Unknown options first, then the number of file names, as the command has always checked.
void check_leftovers(const CLI::App& job) {
  std::size_t files = job.count("INPUT") + job.count("OUTPUT");
  bool only_files = false;
  for (const std::string& a : job.remaining()) {
    if (a == "--") {
      only_files = true;
      continue;
    }
    if (!only_files && a.size() >= 2 && a[0] == '-') usage("unknown option '" + a + "'");
    ++files;
  }
  if (files != 2)
    usage("expected INPUT and OUTPUT, got " + std::to_string(files) + " file name(s)");
}

// OUTPUT may be INPUT only with --overwrite-input; every other written file differs from both
// and from the others.
void check_files(const JobOptions& o,
                 const std::vector<std::pair<std::string, std::string>>& outputs) {
  if (o.output == o.input && !o.overwrite_input)
    usage("OUTPUT is the INPUT file; pass --overwrite-input to replace it");
  for (std::size_t i = 1; i < outputs.size(); ++i) {
    const auto& [name, file] = outputs[i];
    if (file == o.input || file == o.output)
      usage("the " + name + " file must differ from INPUT and OUTPUT");
    for (std::size_t j = 1; j < i; ++j)
      if (file == outputs[j].second)
        usage("the " + outputs[j].first + " and " + name + " files must differ");
  }
}

CLI::App* add_job(CLI::App& app, const std::string& name, const std::string& description) {
  CLI::App* job = app.add_subcommand(name, description);
  add_help_and_version(*job);
  job->allow_extras();
  return job;
}

}  // namespace

std::vector<std::pair<std::string, std::string>> output_files(const JobOptions& o) {
  std::vector<std::pair<std::string, std::string>> files = {{"OUTPUT", o.output}};
  if (!o.report.empty()) files.emplace_back("--report", o.report);
  return files;
}

std::vector<std::pair<std::string, std::string>> output_files(const FlattenOptions& o) {
  std::vector<std::pair<std::string, std::string>> files =
      output_files(static_cast<const JobOptions&>(o));
  if (!o.settings.svg_file.empty()) files.emplace_back("--svg-file", o.settings.svg_file);
  if (!o.settings.dxf_file.empty()) files.emplace_back("--dxf-file", o.settings.dxf_file);
  if (!o.settings.pdf_file.empty()) files.emplace_back("--pdf-file", o.settings.pdf_file);
  if (!o.settings.marker_svg_file.empty())
    files.emplace_back("--marker-svg-file", o.settings.marker_svg_file);
  if (!o.settings.marker_dxf_file.empty())
    files.emplace_back("--marker-dxf-file", o.settings.marker_dxf_file);
  return files;
}

CommandLine parse_command_line(std::vector<std::string> args) {
  CommandLine line;
  CLI::App app(
      "Makes triangle mesh patches nearly developable: cuttable from flat sheet\n"
      "material without stretching; splits meshes into such patches and flattens\n"
      "them into a cutting pattern.\n"
      "Without a subcommand, `quasidev INPUT OUTPUT [options]` runs `approximate`.\n"
      "`quasidev batch INPUTS... -o OUT` runs them over many files (the Python package;\n"
      "`quasidev batch --help`).\n",
      "quasidev");
  app.get_formatter()->column_width(25);
  app.footer(
      "Lengths are in model units, or in AE (the input's average edge length) where the\n"
      "name ends in -ae; angles in degrees. docs/reference/ lists every option.\n"
      "Exit status: 0 success; 1 bad input or engine error; 2 bad command line. On error\n"
      "one line 'quasidev: error: REASON' goes to stderr and no file is written.");
  add_help_and_version(app);
  CLI::App* approximate = add_job(
      app, "approximate",
      "Makes the patches of a triangle mesh nearly developable (Zeng et al., \"Least squares\n"
      "quasi-developable mesh approximation\", CAGD 2012) and writes the result as a binary "
      "PLY.\n");
  add_approximate_options(*approximate, line.approximate);
  CLI::App* segment = add_job(
      app, "segment",
      "Splits a triangle mesh into nearly developable patches (D-Charts: Julius, Kraevoy,\n"
      "Sheffer, Eurographics 2005) and writes it as a binary PLY with the patch id per face.\n");
  add_segment_options(*segment, line.segment);
  CLI::App* flatten = add_job(
      app, "flatten",
      "Flattens every patch of a triangle mesh into a pattern piece (cut to a disk where it is\n"
      "not one, then as rigid as possible: Liu et al., \"A local/global approach to mesh\n"
      "parameterization\", SGP 2008), lays the pieces out at true scale and writes the mesh\n"
      "with their texture coordinates, the stretch per face and optionally the pattern as SVG\n"
      "and DXF.\n");
  add_flatten_options(*flatten, line.flatten);
  const bool names_job =
      !args.empty() &&
      (args[0] == "-h" || args[0] == "--help" || args[0] == "--version" ||
       !app.get_subcommands([&](const CLI::App* s) { return s->check_name(args[0]); }).empty());
  if (!names_job) args.insert(args.begin(), approximate->get_name());
  line.job = segment->check_name(args[0])   ? Job::Segment
             : flatten->check_name(args[0]) ? Job::Flatten
                                            : Job::Approximate;
  const CLI::App& job = line.job == Job::Segment   ? *segment
                        : line.job == Job::Flatten ? *flatten
                                                   : *approximate;
  std::reverse(args.begin(), args.end());  // CLI11 takes the arguments last first
  try {
    app.parse(args);
  } catch (const CLI::CallForHelp&) {
    line.print = app.help("", CLI::AppFormatMode::All);
    return line;
  } catch (const CLI::CallForVersion& e) {
    line.print = std::string(e.what()) + "\n";
    return line;
  } catch (const CLI::ArgumentMismatch& e) {  // "NAME: 1 required TEXT missing"
    const std::string what = e.what();
    usage(what.substr(0, what.find(':')) + " needs a value");
  } catch (const CLI::RequiredError&) {  // INPUT or OUTPUT missing
    check_leftovers(job);
  } catch (const CLI::ParseError& e) {
    usage(e.what());
  }
  check_leftovers(job);
  if (line.job == Job::Segment)
    check_files(line.segment, output_files(line.segment));
  else if (line.job == Job::Flatten)
    check_files(line.flatten, output_files(line.flatten));
  else
    check_files(line.approximate, output_files(line.approximate));
  const params::FlattenSettings& flat = line.flatten.settings;
  if (line.job == Job::Flatten) {
    const bool model = flat.unit == params::PatternUnit::Model;
    if (model && !flat.pdf_file.empty())
      usage(
          "--pdf-file prints at true scale: it needs the model's length unit, --unit mm, cm or in");
    if (model && !flat.dxf_file.empty() && flat.dxf_style == params::DxfStyle::Aama)
      usage("--dxf-style aama declares the pattern's units: it needs --unit mm, cm or in");
    if (flat.marker_width <= 0 && !(flat.marker_svg_file.empty() && flat.marker_dxf_file.empty()))
      usage(
          "--marker-svg-file and --marker-dxf-file need the fabric's width: pass --marker-width "
          "WIDTH");
  }
  return line;
}

}  // namespace qd::cli
