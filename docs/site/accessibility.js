// Keyboard access to what scrolls sideways (WCAG 2.1.1; the axe rule scrollable-region-focusable) and no
// invisible stop on the way (2.4.7). Added by mkdocs.yml's extra_javascript.
// - mkdocs-material wraps each table in a scrolling <div class="md-typeset__scrollwrap"> when the page loads:
//   each becomes a named region with tabindex 0;
// - a display equation wider than the page (at 320 px, or with WCAG text spacing) scrolls: it becomes a
//   region named "equation" with tabindex 0 while it does, and leaves the tab order when it fits again;
// - the search results' scrolling box is a tab stop only while it holds results (empty, it has no height and
//   its focus would be invisible).
const makeRegion = (element, name) => {
  element.setAttribute("tabindex", "0");
  element.setAttribute("role", "region");
  element.setAttribute("aria-label", name);
};

const markScrollingMath = () => {
  for (const math of document.querySelectorAll(".MathJax_Display, .MathJax_SVG_Display, mjx-container[display]")) {
    if (math.scrollWidth > math.clientWidth + 1) makeRegion(math, "equation");
    else if (math.getAttribute("aria-label") === "equation") {
      for (const name of ["tabindex", "role", "aria-label"]) math.removeAttribute(name);
    }
  }
};

const searchStopOnlyWithResults = () => {
  const wrap = document.querySelector(".md-search__scrollwrap");
  const list = document.querySelector(".md-search-result__list");
  if (!wrap || !list) return;
  const update = () => wrap.setAttribute("tabindex", list.children.length ? "0" : "-1");
  new MutationObserver(update).observe(list, {childList: true});
  update();
};

document$.subscribe(() => {
  for (const wrap of document.querySelectorAll(".md-typeset__scrollwrap:not([tabindex])")) makeRegion(wrap, "table");
  markScrollingMath();
  searchStopOnlyWithResults();
});
let pending = false; // MathJax typesets after the page loads: look again, once a frame, whenever nodes come
new MutationObserver(() => {
  if (pending) return;
  pending = true;
  requestAnimationFrame(() => {
    pending = false;
    markScrollingMath();
  });
}).observe(document.body, {childList: true, subtree: true});
window.addEventListener("resize", markScrollingMath);
