#include <csignal>
#include <iostream>

#include "cli.h"
#include "holefill/output_file.h"

int main(int argc, char** argv) {
  // A closed standard output (`holefill fill ... | head -1`) is reported after the mesh is saved
  // instead of ending the process before it.
  std::signal(SIGPIPE, SIG_IGN);
  holefill::remove_partial_files_on_signals();
  return holefill::cli::run(std::vector<std::string>(argv + 1, argv + argc), std::cin, std::cout,
                            std::cerr);
}
