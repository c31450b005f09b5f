// After MathJax has typeset the page: an inline formula wider than its column gets the class "wide-inline"
// (paper_repro.css lets it scroll inside its own box instead of widening the page).
(function () {
  function mark() {
    document.querySelectorAll('mjx-container[jax="CHTML"]:not([display="true"])').forEach(function (m) {
      var col = m.closest('p, li, dd, td, th, div, section');   // the column (span.math is as wide as m)
      if (col && m.getBoundingClientRect().width > col.getBoundingClientRect().width) m.classList.add('wide-inline');
    });
  }
  function whenTypeset() {
    if (window.MathJax && MathJax.startup && MathJax.startup.promise) MathJax.startup.promise.then(mark);
    else setTimeout(whenTypeset, 50);
  }
  window.addEventListener('load', whenTypeset);
  window.addEventListener('resize', mark);
})();
