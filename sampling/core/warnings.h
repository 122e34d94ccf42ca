#pragma once
// One-line warnings and notices on stderr. Libraries warn through here, never to stderr
// directly, so that a process can hold its warnings back: under mpirun every rank loads the
// same scene and meets most of the same conditions, and only rank 0 speaks; the renderer
// hands the other ranks' held lines to rank 0 after a distributed render
// (docs/distributed.md), which prints those it has not printed itself.
#include <string>
#include <vector>

namespace pdrt {

// Prints `line` and a newline on stderr, or keeps it when this process holds its warnings.
// `kind` tells warnings apart from their details (the first pixel, a count): a held line of
// a kind already printed is not printed again. Empty: the line is its own kind.
void warn(const std::string& line, const std::string& kind = "");

// From now on this process keeps its warnings instead of printing them.
void hold_warnings();

// The lines held so far, each as kind + '\n' + line, and forgets them.
std::vector<std::string> take_held_warnings();

// Prints the held lines another process handed over (take_held_warnings' format) whose kind
// this process has not printed yet.
void print_held_warnings(const std::vector<std::string>& held);

}  // namespace pdrt
