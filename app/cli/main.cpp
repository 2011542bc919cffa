#include <csignal>
#include <iostream>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "cli.h"
#include "holefill/output_file.h"

int main(int argc, char** argv) {
  // A closed standard output (`holefill fill ... | head -1`) is reported after the mesh is saved
  // instead of ending the process before it.
  std::signal(SIGPIPE, SIG_IGN);
  holefill::remove_partial_files_on_signals();
#if defined(__GLIBC__)
  // Large arrays go back to the system when freed: by default glibc raises this threshold to the
  // size of the largest array freed, after which the repairs' arrays of a big mesh stayed in the
  // heap, held while the filled mesh was written (a sixth of the peak on a 1.4M-face mesh).
  mallopt(M_MMAP_THRESHOLD, 128 * 1024);
#endif
  return holefill::cli::run(std::vector<std::string>(argv + 1, argv + argc), std::cin, std::cout,
                            std::cerr);
}
