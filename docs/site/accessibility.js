// Keyboard access to the tables that scroll sideways: mkdocs-material wraps each table in a scrolling
// <div class="md-typeset__scrollwrap"> when the page loads; each becomes a named region with tabindex 0
// (WCAG 2.1.1; the axe rule scrollable-region-focusable). Added by mkdocs.yml's extra_javascript.
document$.subscribe(() => {
  for (const wrap of document.querySelectorAll(".md-typeset__scrollwrap:not([tabindex])")) {
    wrap.setAttribute("tabindex", "0");
    wrap.setAttribute("role", "region");
    wrap.setAttribute("aria-label", "table");
  }
});
