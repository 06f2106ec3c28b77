// A classic script (not a module), so that it runs where the page's modules cannot: opened from
// disk (file://), browsers refuse to load ES modules and WebAssembly, and the page would stay
// empty with the reason in the console only. This puts the reason, and the one line that serves
// the folder, at the top of the page.
(function servedCheck() {
  if (location.protocol !== 'file:') return;
  function show() {
    var folder = decodeURIComponent(location.pathname.replace(/[^/]*$/, ''));
    var note = document.createElement('div');
    note.id = 'served-note';
    note.setAttribute('role', 'alert');
    var title = document.createElement('strong');
    title.textContent = 'This page must be served over http: ';
    var why = document.createTextNode('browsers do not run its modules and WebAssembly from a file. In a terminal, serve this folder with');
    var command = document.createElement('code');
    command.textContent = 'python3 -m http.server 8000 --directory "' + folder + '"';
    var then = document.createTextNode(' and open http://localhost:8000/ (any static server will do).');
    note.append(title, why, document.createElement('br'), command, then);
    document.body.prepend(note);
  }
  if (document.body) show();
  else document.addEventListener('DOMContentLoaded', show);
}());
