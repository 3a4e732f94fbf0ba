// Runs before the page paints (a classic script in <head>): the theme option
// of the address (theme=light|dark) becomes <html data-theme>, so a dark embed
// never flashes white. theme.css reads it; without it the system setting rules.
(function () {
  var m = /[?&]theme=(light|dark|auto)(?:&|$)/.exec(location.hash);
  if (m && m[1] !== "auto") document.documentElement.setAttribute("data-theme", m[1]);
})();
