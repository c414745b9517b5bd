// The search page of the site: MiniSearch over the index written at build time
// (search-index.js); the query comes from the page's ?q= or its input box. Results are grouped by
// the kind of page they come from, in the order of #search-kinds (the document's sections before the
// golden cases), best first within a group; each shows a snippet of its text with the words that
// matched marked (<mark>), cut around the first of them.
"use strict";
(function () {
  const options = JSON.parse(document.getElementById("search-options").textContent);
  const kinds = JSON.parse(document.getElementById("search-kinds").textContent);
  const term = window.CBF_SEARCH_TERM;
  const index = MiniSearch.loadJSON(window.CBF_SEARCH_INDEX, { ...options, processTerm: term });
  const input = document.getElementById("search-input");
  const out = document.getElementById("search-results");
  const status = document.getElementById("search-status");
  const root = document.body.getAttribute("data-root") || "";
  const SPLIT = /([\n\r\p{Z}\p{P}]+)/u; // MiniSearch's own word boundary (kept in the pieces by split)
  const BEFORE = 60; // characters of context before the first match
  const WORDS = 32; // words a snippet shows at most
  const SHOWN = 50; // results a group lists at most

  // Where the first word of text that matched starts: a matched term (lower case, perhaps without its
  // plural s) found at the start of a word, by the browser's own string search (fast on long parts).
  function firstMatch(text, matched) {
    const lower = text.toLowerCase();
    let first = -1;
    for (const t of matched) {
      for (let at = lower.indexOf(t); at >= 0 && (first < 0 || at < first); at = lower.indexOf(t, at + 1)) {
        if (at === 0 || SPLIT.test(text[at - 1])) { first = at; break; }
      }
    }
    return first;
  }

  // The snippet of a result: text nodes and <mark> elements (never HTML from the text), from about
  // BEFORE characters ahead of the first match, WORDS words at most.
  function snippet(text, matched) {
    const hit = (w) => matched.has(term(w));
    const at = firstMatch(text, matched);
    let from = Math.max(0, at - BEFORE);
    while (from > 0 && from < at && !SPLIT.test(text[from - 1])) from++; // start at a word
    const pieces = text.slice(from, from + 40 * WORDS).split(SPLIT).slice(0, 2 * WORDS - 1); // word, separator, ...
    const span = document.createElement("span");
    span.className = "snippet";
    let plain = from > 0 ? "\u2026 " : ""; // text between two marks: one text node
    for (let k = 0; k < pieces.length; k++) {
      if (k % 2 === 0 && pieces[k] && hit(pieces[k])) {
        span.appendChild(document.createTextNode(plain));
        plain = "";
        const mark = document.createElement("mark");
        mark.textContent = pieces[k];
        span.appendChild(mark);
      } else {
        plain += pieces[k];
      }
    }
    if (from + pieces.join("").length < text.length) plain += " \u2026";
    span.appendChild(document.createTextNode(plain));
    return span;
  }

  function item(hit) {
    const li = document.createElement("li");
    const a = document.createElement("a");
    a.href = root + hit.url;
    a.textContent = hit.title;
    const where = document.createElement("span");
    where.className = "where";
    where.textContent = " \u00b7 " + hit.page;
    li.appendChild(a);
    li.appendChild(where);
    li.appendChild(snippet(hit.text, new Set(hit.terms)));
    return li;
  }

  function show(query) {
    out.textContent = "";
    const q = query.trim();
    if (!q) { status.textContent = "Type a word: a command, a field, a check id, a clause number."; return; }
    const hits = index.search(q, { prefix: true, fuzzy: 0.15, combineWith: "AND" });
    status.textContent = hits.length + (hits.length === 1 ? " result" : " results") + " for \u201c" + q + "\u201d";
    for (const kind of Object.keys(kinds)) {
      const group = hits.filter((h) => h.kind === kind); // MiniSearch's order: best first
      if (!group.length) continue;
      const section = document.createElement("section");
      section.setAttribute("data-kind", kind);
      const h2 = document.createElement("h2");
      h2.textContent = kinds[kind] + " (" + group.length + ")";
      const ol = document.createElement("ol");
      for (const hit of group.slice(0, SHOWN)) ol.appendChild(item(hit));
      section.appendChild(h2);
      section.appendChild(ol);
      out.appendChild(section);
    }
  }
  const q = new URLSearchParams(window.location.search).get("q") || "";
  input.value = q;
  input.addEventListener("input", function () { show(input.value); });
  show(q);
  document.body.setAttribute("data-search-ready", String(index.documentCount));
})();
