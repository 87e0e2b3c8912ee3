// `voltree web`: a self-contained static page that draws an asset or a scene with WebGL2.
//
// The folder holds index.html, voltree.js (the page's renderer, web/page/) and data.js: the
// scene (instances, ground) and every asset's .vtree bytes in base64. Assets travel inside a
// script because browsers refuse fetch() and XMLHttpRequest on file:// pages, while a <script
// src> next to the page loads from disk and from any static server alike. The assets are written
// with raw (not zstd) chunks, so the page reads the .vtree format with no decompressor; it checks
// every checksum, count and index as core/vtree.cpp does (docs/web.md).
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace voltree {

struct WebPageOptions {
  std::filesystem::path input;         // a .vtree asset or a scene .json
  std::filesystem::path output;        // the page's folder (built aside, renamed into place)
  std::filesystem::path asset_folder;  // scenes: where their assets are looked up (default: the scene's folder)
  bool force = false;                  // replace an existing output folder
  void Check() const;
};

struct WebPageResult {
  std::vector<std::string> files;  // inside the output folder
  size_t bytes = 0;                // all files together: what a browser loads
  size_t assets = 0, instances = 0;
};

WebPageResult WriteWebPage(const WebPageOptions& options);

}  // namespace voltree
