// The search page of the site: MiniSearch over the index written at build time
// (search-index.js); the query comes from the page's ?q= or its input box.
"use strict";
(function () {
  const options = JSON.parse(document.getElementById("search-options").textContent);
  const index = MiniSearch.loadJSON(window.CBF_SEARCH_INDEX, options);
  const input = document.getElementById("search-input");
  const out = document.getElementById("search-results");
  const status = document.getElementById("search-status");
  const root = document.body.getAttribute("data-root") || "";

  function show(query) {
    out.textContent = "";
    const q = query.trim();
    if (!q) { status.textContent = "Type a word: a command, a field, a check id, a clause number."; return; }
    const hits = index.search(q, { prefix: true, fuzzy: 0.15, combineWith: "AND" });
    status.textContent = hits.length + (hits.length === 1 ? " result" : " results") + " for \u201c" + q + "\u201d";
    for (const hit of hits.slice(0, 100)) {
      const li = document.createElement("li");
      const a = document.createElement("a");
      a.href = root + hit.url;
      a.textContent = hit.title;
      const where = document.createElement("span");
      where.className = "where";
      where.textContent = " \u00b7 " + hit.page;
      li.appendChild(a);
      li.appendChild(where);
      out.appendChild(li);
    }
  }
  const q = new URLSearchParams(window.location.search).get("q") || "";
  input.value = q;
  input.addEventListener("input", function () { show(input.value); });
  show(q);
  document.body.setAttribute("data-search-ready", String(index.documentCount));
})();
