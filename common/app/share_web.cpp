// "copy link" in the browser: the page's URL with the view's values as ?set=name=value, shown in
// the address bar (history.replaceState) and copied to the clipboard where the page may (share.hpp).
// The page (tools/wasm/shell.html, shadowlab.share) builds the URL: it keeps the size and UI scale.
#include <emscripten.h>

#include "app/share.hpp"

namespace shadowlab {

const char* shareLabel() { return "copy link"; }

std::string shareView(const ParamValues& changed, const std::string& /*lesson*/) {
  std::string lines;  // name=value, one a line: the page URL-encodes each
  for (const auto& [name, value] : changed) lines += name + "=" + value + "\n";
  char url[4096] = "";
  EM_ASM(
      {
        const url = Module.shareView ? Module.shareView(UTF8ToString($0)) : '';
        stringToUTF8(url, $1, $2);
      },
      lines.c_str(), url, int(sizeof url));
  return url[0] ? std::string("link copied (and in the address bar): ") + url
                : "copy link: this page cannot set its address";
}

}  // namespace shadowlab
