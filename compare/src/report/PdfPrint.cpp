#include "vesica/compare/report/PdfPrint.h"

#include <chrono>
#include <fstream>

#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Error.h"
#include "vesica/core/HelperProgram.h"

namespace vesica::compare {
namespace {

namespace fs = std::filesystem;

// A page prints in seconds; chromium waiting on something that never comes is stopped.
constexpr std::chrono::seconds kPrintDeadline{120};

bool starts_like_pdf(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  char head[5] = {};
  in.read(head, 5);
  return in && std::string(head, 5) == "%PDF-" && fs::file_size(p) > 1000;
}

}  // namespace

std::string print_pdf(const fs::path& html, const fs::path& pdf) {
  std::string why;
  if (!find_program("chromium")) {
    why = "chromium is not installed";
  } else {
    try {
      const TemporaryFolder profile("compare-chromium");
      write_atomically(pdf, [&](const fs::path& tmp) {
        const HelperResult run =
            run_helper({"chromium", "--headless", "--no-sandbox", "--disable-gpu",
                        "--disable-background-networking", "--disable-component-update",
                        "--no-first-run", "--disable-dev-shm-usage", "--no-pdf-header-footer",
                        "--user-data-dir=" + (profile.path() / "profile").string(),
                        "--print-to-pdf=" + tmp.string(), "file://" + fs::absolute(html).string()},
                       profile.path() / "chromium.log", kPrintDeadline);
        if (run.exit_code != 0 || !fs::exists(tmp) || !starts_like_pdf(tmp))
          fail(pdf.string(), run.timed_out ? "headless chromium printed no PDF within " +
                                                 std::to_string(kPrintDeadline.count()) + " s"
                                           : "headless chromium did not print a PDF (exit " +
                                                 std::to_string(run.exit_code) + ")");
      });
    } catch (const Error& e) {
      why = e.what();
    }
  }
  if (!why.empty()) {
    std::error_code ec;
    fs::remove(pdf, ec);
  }
  return why;
}

}  // namespace vesica::compare
