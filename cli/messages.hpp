#pragma once
// The one way cmx speaks on stderr. Every error, warning and note is a line "cmx CMD: text", the
// command named once (main sets it), and every byte that a terminal would not show as text (control
// characters, bytes that are not UTF-8) is printed as \xHH, so a message quoting a binary file
// cannot garble the terminal.
#include <string>
#include <string_view>

namespace cmx::cli {

// The command that is speaking ("map", ...); main sets it before running the command.
void set_command_name(std::string_view name);
const std::string& command_name();

// --quiet: notes are dropped (errors and warnings are not).
void set_quiet(bool quiet);
bool quiet();

// `text` with control characters, DEL and bytes outside well-formed UTF-8 as \xHH.
std::string printable(std::string_view text);

// "cmx CMD: text" on stderr, always (errors, warnings).
void message(std::string_view text);
// The same, unless --quiet (what a command did: "wrote ...").
void note(std::string_view text);

}  // namespace cmx::cli
