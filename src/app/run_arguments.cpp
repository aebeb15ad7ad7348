#include "biphasic/app/run_arguments.hpp"

#include <stdexcept>

namespace biphasic {

RunArguments parse_run_arguments(const std::vector<std::string>& args, bool foreign_options) {
  RunArguments r;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&](const char* flag) {
      if (i + 1 >= args.size()) throw std::invalid_argument(std::string(flag) + " needs a value");
      return args[++i];
    };
    if (a == "-o" || a == "--output") {
      r.output_dir = value("-o");
    } else if (a == "--set") {
      r.overrides.push_back(value("--set"));
    } else if (a.rfind("--set=", 0) == 0) {
      r.overrides.push_back(a.substr(6));
    } else if (a == "--restart") {
      r.restart_dir = value("--restart");
    } else if (a == "--overwrite") {
      r.options.overwrite = true;
    } else if (a == "--quiet" || a == "-q") {
      r.options.quiet = true;
    } else if (!a.empty() && a[0] == '-') {
      if (!foreign_options) throw std::invalid_argument("unknown option '" + a + "'");
      if (i + 1 < args.size() && !args[i + 1].empty() && args[i + 1][0] != '-') ++i;
    } else if (r.case_path.empty()) {
      r.case_path = a;
    } else {
      throw std::invalid_argument("more than one case file given ('" + r.case_path + "', '" + a +
                                  "')");
    }
  }
  if (r.case_path.empty()) throw std::invalid_argument("run needs a case file");
  return r;
}

void continue_in_restart_folder(RunArguments& r) {
  if (r.restart_dir.empty()) return;
  if (!r.output_dir.empty() && r.output_dir != r.restart_dir)
    throw std::invalid_argument("--restart " + r.restart_dir + " writes into " + r.restart_dir +
                                "; -o " + r.output_dir + " contradicts it");
  if (r.options.overwrite)
    throw std::invalid_argument("--restart continues a run, --overwrite deletes it: give one");
  r.output_dir = r.restart_dir;
  r.options.restart = true;
}

}  // namespace biphasic
