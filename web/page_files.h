// The static files of the web page (web/page/), compiled into the binary.
#pragma once

#include <string_view>

namespace voltree {

// The bytes of web/page/NAME ("index.html", "voltree.js"); throws Error for an unknown name.
std::string_view PageFile(std::string_view name);

}  // namespace voltree
