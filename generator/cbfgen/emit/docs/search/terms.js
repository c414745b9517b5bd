// The one term rule of the site's search, for the index (build_index.cjs, in node) and for the query
// (search.js, in the page) alike: a word in lower case, a plural's final "s" dropped ("checksums" is
// found by "checksum", "checks" by "check"; "ss" stays, as in "address"). MiniSearch calls it as its
// processTerm; the page also uses it to mark the words of a result that matched.
"use strict";
(function (root) {
  function cbfTerm(term) {
    const t = term.toLowerCase();
    return t.length > 3 && t.endsWith("s") && !t.endsWith("ss") ? t.slice(0, -1) : t;
  }
  if (typeof module !== "undefined" && module.exports) {
    module.exports = cbfTerm;
  } else {
    root.CBF_SEARCH_TERM = cbfTerm;
  }
})(this);
