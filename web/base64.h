// Base64 (RFC 4648, with padding): how the page carries binary assets inside a script file.
#pragma once

#include <string>
#include <string_view>

namespace voltree {

std::string EncodeBase64(std::string_view bytes);

}  // namespace voltree
