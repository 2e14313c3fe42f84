#include "vesica/compare/report/PdfPrint.h"

#include <cstdlib>
#include <fstream>

#include <unistd.h>

#include "report/ShellQuote.h"
#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Error.h"

namespace vesica::compare {
namespace {

namespace fs = std::filesystem;

bool starts_like_pdf(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  char head[5] = {};
  in.read(head, 5);
  return in && std::string(head, 5) == "%PDF-" && fs::file_size(p) > 1000;
}

}  // namespace

std::string print_pdf(const fs::path& html, const fs::path& pdf) {
  std::string why;
  if (std::system("command -v chromium >/dev/null 2>&1") != 0) {
    why = "chromium is not installed";
  } else {
    const fs::path profile =
        fs::temp_directory_path() / ("vesica-compare-chromium-" + std::to_string(::getpid()));
    try {
      write_atomically(pdf, [&](const fs::path& tmp) {
        const std::string cmd =
            "timeout 120 chromium --headless --no-sandbox --disable-gpu "
            "--disable-background-networking --disable-component-update --no-first-run "
            "--disable-dev-shm-usage --no-pdf-header-footer --user-data-dir=" +
            detail::shell_quote(profile.string()) +
            " --print-to-pdf=" + detail::shell_quote(tmp.string()) + " " +
            detail::shell_quote("file://" + fs::absolute(html).string()) + " >/dev/null 2>&1";
        const int status = std::system(cmd.c_str());
        if (status != 0 || !fs::exists(tmp) || !starts_like_pdf(tmp))
          fail(pdf.string(),
               "headless chromium did not print a PDF (exit " + std::to_string(status) + ")");
      });
    } catch (const Error& e) {
      why = e.what();
    }
    std::error_code ec;
    fs::remove_all(profile, ec);
  }
  if (!why.empty()) {
    std::error_code ec;
    fs::remove(pdf, ec);
  }
  return why;
}

}  // namespace vesica::compare
