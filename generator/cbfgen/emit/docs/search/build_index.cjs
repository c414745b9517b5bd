// The site's search index, built once at `make docs` time with MiniSearch (npm, pinned in
// package-lock.json): reads the documents as JSON on stdin ({options, documents}), writes
// search-index.js, which sets window.CBF_SEARCH_INDEX to the serialised index (the page
// loads it with MiniSearch.loadJSON: no index is built in the browser, nothing is fetched,
// so the site searches offline and from file://). Terms go through terms.js, as the page's do.
"use strict";
const path = require("path");
const MiniSearch = require(path.join(process.argv[2], "minisearch", "dist", "cjs", "index.cjs"));
const cbfTerm = require("./terms.js");

let input = "";
process.stdin.setEncoding("utf8");
process.stdin.on("data", (chunk) => { input += chunk; });
process.stdin.on("end", () => {
  const { options, documents } = JSON.parse(input);
  const index = new MiniSearch({ ...options, processTerm: cbfTerm });
  index.addAll(documents);
  process.stdout.write("window.CBF_SEARCH_INDEX = " + JSON.stringify(JSON.stringify(index)) + ";\n");
});
