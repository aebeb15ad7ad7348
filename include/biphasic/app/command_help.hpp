// The command line's help texts: the whole program's (biphasic --help) and each command's
// (biphasic COMMAND --help, biphasic help COMMAND), with its arguments, options and exit status.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace biphasic {

/// biphasic --help: every command in one page, with what `run` writes.
std::string program_usage();

/// The commands that have a help of their own: run, check, schema, help.
std::vector<std::string> command_names();

/// The help of one command (usage lines, what it does, its arguments and options, environment
/// variables it reads, exit status); std::nullopt if `command` is none of command_names().
std::optional<std::string> command_help(std::string_view command);

}  // namespace biphasic
