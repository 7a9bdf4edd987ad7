// Keyboard access to what scrolls sideways (WCAG 2.1.1; the axe rule scrollable-region-focusable). Added by
// mkdocs.yml's extra_javascript.
// - mkdocs-material wraps each table in a scrolling <div class="md-typeset__scrollwrap"> when the page loads:
//   each becomes a named region with tabindex 0, marked data-scrolls while it is too wide for its column;
// - a display equation wider than the page (at 320 px, or with WCAG text spacing) scrolls: it becomes a
//   region named "equation" with tabindex 0 while it does, and leaves the tab order when it fits again;
// - a block of code (tools/site_hooks.py makes each a region named "code") is a tab stop while it scrolls, named
//   "code, scrolls sideways", and leaves the tab order when it fits; so is a notebook output that scrolls, named
//   "output, scrolls sideways" (nbconvert made every output a tab stop of no name; the site hooks drop that);
// - material's search results box is a region named "search results" but no tab stop (tabindex -1): material makes it
//   one, yet Tab from the search box closes the search overlay, so the box would take the focus unseen (WCAG 2.4.7);
//   its results are reached from the search box by the arrow keys, as material intends (accessibility.css hides
//   the box while the overlay is closed).
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

const scrolls = (element) => element.scrollWidth > element.clientWidth + 1;
const SCROLLS = ", scrolls sideways";
const markScrollingBlocks = () => {
  for (const code of document.querySelectorAll('[role="region"][aria-label^="code"]')) {
    if (scrolls(code)) makeRegion(code, "code" + SCROLLS);
    else {
      code.removeAttribute("tabindex");
      code.setAttribute("aria-label", "code");
    }
  }
  for (const output of document.querySelectorAll(".jp-OutputArea-output")) {
    const overflow = getComputedStyle(output).overflowX;
    if (scrolls(output) && (overflow === "auto" || overflow === "scroll")) makeRegion(output, "output" + SCROLLS);
    else if (output.getAttribute("aria-label") === "output" + SCROLLS) {
      for (const name of ["tabindex", "role", "aria-label"]) output.removeAttribute(name);
    }
  }
};

// A table wider than its column scrolls sideways in its wrapper (material's, or a figure description's): the wrapper
// says so in words above the table (notebook-pages.css draws the note, data-scrolls turns it on), since an overlay
// scroll bar is not always shown.
const markScrollingTables = () => {
  for (const wrap of document.querySelectorAll(".md-typeset__scrollwrap, .figure-described-table")) {
    const scrolls = wrap.scrollWidth > wrap.clientWidth + 1;
    wrap.toggleAttribute("data-scrolls", scrolls);
    if (wrap.classList.contains("md-typeset__scrollwrap")) {  // a description's table keeps its own name
      wrap.setAttribute("aria-label", scrolls ? "table, scrolls sideways" : "table");
    }
  }
};

// - material's icons (inline SVG in the header, search, navigation, "Back to top" and footer) sit inside named links
//   and buttons, or beside text that says the same: a screen reader's tree lists each as an unnamed image, so
//   they are hidden from it (aria-hidden), as GitHub's copy icons already are.
const ICONS = ".md-header svg, .md-search svg, .md-nav svg, .md-top svg, .md-footer svg, .md-source svg, .md-content__button svg";
const hideIcons = () => {
  for (const icon of document.querySelectorAll(ICONS)) {
    if (!icon.hasAttribute("aria-label") && !icon.querySelector("title")) icon.setAttribute("aria-hidden", "true");
  }
};

document$.subscribe(() => {
  for (const wrap of document.querySelectorAll(".md-typeset__scrollwrap:not([tabindex])")) makeRegion(wrap, "table");
  for (const results of document.querySelectorAll(".md-search__scrollwrap")) {
    makeRegion(results, "search results");
    results.setAttribute("tabindex", "-1"); // a scrolling box with no tabindex is a tab stop in Chromium too
  }
  markScrollingTables();
  markScrollingBlocks();
  markScrollingMath();
  hideIcons();
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
// a figure's longer description and an answer open closed: their tables and code are measured again when opened
document.addEventListener(
  "toggle",
  () => {
    markScrollingTables();
    markScrollingBlocks();
  },
  true,
);
window.addEventListener("resize", () => {
  markScrollingTables();
  markScrollingBlocks();
  markScrollingMath();
});
// The drawer's panels. Material's navigation drawer holds each nested section in a panel (a <nav> after a checkbox,
// input.md-nav__toggle) that slides in over its parent when the box is ticked: a click on the section's label opens
// it ("Chapters >"), a click on the panel's title closes it ("< Chapters"). Those labels take no focus; below the
// breakpoint each becomes a button the Tab key reaches (WCAG 2.1.1), named by its text, an opener saying whether its
// panel is open (aria-expanded); Enter and Space press it, and the focus goes on to the panel then shown: to its
// title once opened, back to the opener once closed.
const drawerPanels = (() => {
  const toggleOf = (nav) => nav.parentElement?.querySelector(":scope > input.md-nav__toggle");
  const isPanel = (nav) => nav.classList.contains("md-nav--primary") || !!toggleOf(nav);
  const panelOf = (element) => {
    let nav = element.closest("nav");
    while (nav && !isPanel(nav)) nav = nav.parentElement.closest("nav");
    return nav;
  };
  // the panel shown: from the drawer's root, the panel of each ticked box in turn, down to the last one
  const shown = (navigation) => {
    let panel = navigation.querySelector(".md-nav--primary");
    for (;;) {
      const next = [...panel.querySelectorAll("nav.md-nav")].find(
        (nav) => toggleOf(nav)?.checked && panelOf(nav.parentElement) === panel,
      );
      if (!next) return panel;
      panel = next;
    }
  };
  const FOCUSABLE = "a[href], button, input:not([type=checkbox]), [tabindex]:not([tabindex='-1']):not([tabindex=''])";
  const stops = (panel) => (panel ? [...panel.querySelectorAll(FOCUSABLE)].filter((s) => panelOf(s) === panel) : []);
  const labels = (navigation) =>
    [...navigation.querySelectorAll("label.md-nav__link[for], label.md-nav__title[for]")].filter((label) =>
      document.getElementById(label.htmlFor)?.classList.contains("md-nav__toggle"),
    );
  const press = (label, navigation) => (event) => {
    if (event.key !== "Enter" && event.key !== " ") return;
    event.preventDefault();
    event.stopPropagation(); // material clicks a focused label at Enter too: the panel would open and close again
    label.click(); // ticks or unticks the box: material slides the panel
    const box = document.getElementById(label.htmlFor);
    const opener = navigation.querySelector(`label.md-nav__link[for="${label.htmlFor}"]`);
    const title = navigation.querySelector(`label.md-nav__title[for="${label.htmlFor}"]`);
    (box.checked ? title : opener)?.focus({preventScroll: box.checked});
  };
  const expanded = (navigation) => {
    for (const label of labels(navigation)) {
      if (label.classList.contains("md-nav__link") && label.hasAttribute("role")) {
        label.setAttribute("aria-expanded", String(document.getElementById(label.htmlFor).checked));
      }
    }
  };
  // below the breakpoint (on): every panel's labels are buttons; above it, material's own labels again
  const toggles = (navigation, on) => {
    for (const label of labels(navigation)) {
      if (!label.toolkitPress) {
        label.toolkitPress = press(label, navigation);
        document.getElementById(label.htmlFor).addEventListener("change", () => expanded(navigation));
      }
      if (on) {
        label.setAttribute("tabindex", "0");
        label.setAttribute("role", "button");
        if (label.classList.contains("md-nav__title")) {
          label.setAttribute("aria-label", `Back from ${label.textContent.trim()}`);
        }
        label.addEventListener("keydown", label.toolkitPress);
      } else {
        for (const name of ["role", "aria-label", "aria-expanded"]) label.removeAttribute(name);
        label.setAttribute("tabindex", "");
        label.removeEventListener("keydown", label.toolkitPress);
      }
    }
    expanded(navigation);
  };
  return {shown, stops, toggles};
})();
// Below Material's drawer breakpoint the site's navigation is a drawer off the screen's left edge; closed, its links
// stayed in the tab order, so focus went where no one could see it (WCAG 2.4.7 at 320 px): it is inert while closed.
// Material opens it by a click on the menu icon only (a <label> that takes no focus), so that icon becomes a button
// the keyboard reaches (WCAG 2.1.1), saying whether the drawer is open; Enter or Space opens it and puts the focus on
// the first stop of the panel it shows, Escape closes it and gives the focus back to the button.
(() => {
  const drawer = document.getElementById("__drawer");
  const navigation = document.querySelector(".md-sidebar--primary");
  const button = document.querySelector('label.md-header__button[for="__drawer"]');
  if (!drawer || !navigation) return;
  const narrow = window.matchMedia("(max-width: 76.234375em)"); // Material's own breakpoint for the drawer
  const update = () => {
    navigation.inert = narrow.matches && !drawer.checked;
    button?.setAttribute("aria-expanded", String(drawer.checked));
  };
  const open = (opened) => {
    drawer.checked = opened;
    update();
    if (opened) stops()[0]?.focus();
    else button?.focus();
  };
  if (button) {
    button.setAttribute("tabindex", "0");
    button.setAttribute("role", "button");
    button.setAttribute("aria-label", "The site's navigation");
    button.addEventListener("keydown", (event) => {
      if (event.key !== "Enter" && event.key !== " ") return;
      event.preventDefault();
      event.stopPropagation(); // material's Enter would click the label then focused: a panel's "back" button
      open(!drawer.checked);
    });
  }
  // Open, the drawer covers the page: Tab and Shift+Tab cycle through the stops of the panel it shows (a focus trap,
  // as a dialog's), so the focus never goes to the page hidden behind it (WCAG 2.4.3); Escape closes it, from anywhere
  // in it. Material draws each nested section ("Chapters", a page's contents) as a panel that slides over its parent:
  // the links of the panels under it, or beside it off the screen, still took the focus unseen (WCAG 2.4.7), so the
  // keyboard's stops are those of the panel shown only (drawerPanels).
  const stops = () =>
    drawerPanels.stops(drawerPanels.shown(navigation)).filter(
      (stop) => stop.getClientRects().length && getComputedStyle(stop).visibility !== "hidden",
    );
  document.addEventListener("keydown", (event) => {
    if (!drawer.checked || !narrow.matches) return;
    if (event.key === "Escape") open(false);
    if (event.key !== "Tab") return;
    const all = stops();
    if (!all.length) return;
    event.preventDefault();
    const at = all.indexOf(document.activeElement);
    all[at < 0 ? 0 : (at + (event.shiftKey ? -1 : 1) + all.length) % all.length].focus();
  });
  const toggles = () => drawerPanels.toggles(navigation, narrow.matches);
  narrow.addEventListener("change", toggles);
  toggles();
  drawer.addEventListener("change", update);
  narrow.addEventListener("change", update);
  update();
})();
// The focus may land on a control of an embedded scene (a same-origin frame: srcdoc) that lies below the window's
// edge while the frame's top shows: the browser scrolls the frame's own page, not this one, so the focus was out of
// sight (WCAG 2.4.7, 2.4.3). This page now scrolls the least that brings the control into view, clear of the header.
const showFocusIn = (frame) => (event) => {
  const control = event.target.getBoundingClientRect?.();
  if (!control) return;
  const box = frame.getBoundingClientRect();
  const top = box.top + Math.max(control.top, 0), bottom = box.top + Math.min(control.bottom, frame.clientHeight);
  const header = document.querySelector(".md-header")?.getBoundingClientRect().bottom ?? 0;
  if (bottom > window.innerHeight) window.scrollBy(0, bottom - window.innerHeight + 8);
  else if (top < header) window.scrollBy(0, top - header - 8);
};
const watchFrames = () => {
  for (const frame of document.querySelectorAll("iframe")) {
    const watch = () => {
      const inner = frame.contentDocument; // null for a frame of another origin: the browser's own scrolling stays
      if (inner && !inner.toolkitWatched) {
        inner.toolkitWatched = true;
        inner.addEventListener("focusin", showFocusIn(frame));
      }
    };
    if (!frame.dataset.watched) {
      frame.dataset.watched = "1";
      frame.addEventListener("load", watch);
    }
    watch();
  }
};
document$.subscribe(watchFrames);
