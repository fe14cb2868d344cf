#pragma once
// The `akvf experiment` command: run a manifest (with sharding and resume),
// merge the results folders of shards, and (re)write the reports.
#include <ostream>
#include <string>
#include <vector>

namespace akvf {

int experiment_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace akvf
