// qd_reference: the parameter declarations of every job as documents.
//   qd_reference --json          the declarations as JSON on stdout (the tests read it)
//   qd_reference --write DIR     writes DIR/<job>.md (docs/reference/) for every job
//   qd_reference --check DIR     exit 1, naming them, when DIR's pages differ from what --write
//                                would write (a test runs it on docs/reference/)
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>

#include "approximate_params.h"
#include "flatten_params.h"
#include "jobs.h"
#include "params_json.h"
#include "reference_markdown.h"
#include "segment_params.h"

namespace {

using qd::params::JobNames;
using qd::params::ParamInfo;

struct Job {
  JobNames names;
  std::vector<ParamInfo> params;
};

std::vector<Job> jobs() {
  return {{qd::params::kApproximateJob, qd::params::infos(qd::params::approximate_params())},
          {qd::params::kSegmentJob, qd::params::infos(qd::params::segment_params())},
          {qd::params::kFlattenJob, qd::params::infos(qd::params::flatten_params())}};
}

std::string read(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  if (mode == "--json" && argc == 2) {
    qd::params::Json out = qd::params::Json::object();
    for (const Job& j : jobs())
      out[j.names.command] = {{"filter", j.names.filter},
                              {"python", j.names.python},
                              {"parameters", qd::params::declaration_json(j.params)}};
    std::cout << out.dump(1) << "\n";
    return 0;
  }
  if ((mode == "--write" || mode == "--check") && argc == 3) {
    int stale = 0;
    for (const Job& j : jobs()) {
      const std::string path = std::string(argv[2]) + "/" + j.names.command + ".md";
      const std::string page = qd::params::reference_markdown(j.names, j.params);
      if (mode == "--write") {
        std::ofstream(path, std::ios::binary) << page;
      } else if (read(path) != page) {
        std::cerr << path
                  << " differs from the parameter declarations: run scripts/make_reference.sh\n";
        ++stale;
      }
    }
    return stale ? 1 : 0;
  }
  std::cerr << "usage: qd_reference --json | --write DIR | --check DIR\n";
  return 2;
}
