/* The staff overview, enhanced: the gradebook and progress tables sorted by any column,
   searched by student, and updated every few seconds (pausable; WCAG 2.2.1) from
   the page's own tables route, whose address the pause button carries. Without
   this script the page shows the tables as they were when it loaded. */
(function () {
  var button = document.getElementById("live"), status = document.getElementById("live-status");
  var url = button.dataset.tables, paused = false, timer = null;
  var students = button.dataset.students, seconds = +button.dataset.seconds;
  var find = document.getElementById("find-student"), count = document.getElementById("find-count");
  var sorted = {};  // table id -> {column, direction}, kept across refreshes
  function fill(id, table) {
    var body = document.querySelector("#" + id + " tbody"), fresh = document.createElement("tbody");
    table.rows.forEach(function (row) {
      var tr = document.createElement("tr");
      row.forEach(function (cell, i) {
        var td = document.createElement("td");
        if (i === 0) {
          var a = document.createElement("a"); a.href = students + encodeURIComponent(cell);
          a.textContent = cell; td.appendChild(a);
        } else { td.textContent = cell; }
        tr.appendChild(td);
      });
      fresh.appendChild(tr);
    });
    body.replaceWith(fresh);
    arrange(id);
  }
  function number(text) {  // a cell that is a number sorts as one; "—" and "" last
    var t = text.trim();
    return /^-?[0-9]+([.,][0-9]+)?$/.test(t) ? parseFloat(t.replace(",", ".")) : null;
  }
  function compare(a, b) {
    var x = number(a), y = number(b);
    if (x !== null && y !== null) { return x - y; }
    if (x !== null || y !== null) { return x !== null ? -1 : 1; }
    var blankA = a === "" || a === "—", blankB = b === "" || b === "—";
    if (blankA || blankB) { return blankA === blankB ? 0 : (blankA ? 1 : -1); }
    return a.localeCompare(b, undefined, {numeric: true, sensitivity: "base"});
  }
  function arrange(id) {  // sort by the chosen column, then hide the rows the search misses
    var table = document.getElementById(id), body = table.tBodies[0];
    var rows = Array.prototype.slice.call(body.rows), order = sorted[id];
    if (order) {
      rows.sort(function (r, s) {
        var c = compare(r.cells[order.column].textContent, s.cells[order.column].textContent);
        return order.direction === "ascending" ? c : -c;
      });
      rows.forEach(function (r) { body.appendChild(r); });
    }
    var words = find.value.trim().toLowerCase(), searched = +table.dataset.searched, shown = 0;
    rows.forEach(function (r) {
      var text = Array.prototype.slice.call(r.cells, 0, searched)
        .map(function (c) { return c.textContent.toLowerCase(); }).join(" ");
      r.hidden = words !== "" && text.indexOf(words) < 0;
      if (!r.hidden) { shown += 1; }
    });
    if (id === "gradebook") {
      count.textContent = count.dataset.text.replace("{n}", shown).replace("{m}", rows.length);
    }
  }
  function sortable(id) {
    var heads = document.querySelectorAll("#" + id + " thead th");
    heads.forEach(function (th, column) {
      var button = document.createElement("button");
      button.type = "button"; button.className = "sort"; button.textContent = th.textContent;
      th.textContent = ""; th.appendChild(button);
      button.addEventListener("click", function () {
        var now = sorted[id], direction = now && now.column === column &&
          now.direction === "ascending" ? "descending" : "ascending";
        sorted[id] = {column: column, direction: direction};
        heads.forEach(function (other) { other.removeAttribute("aria-sort"); });
        th.setAttribute("aria-sort", direction);
        arrange(id);
      });
    });
  }
  ["gradebook", "progress"].forEach(sortable);
  document.getElementById("find").hidden = false;
  find.addEventListener("input", function () { arrange("gradebook"); arrange("progress"); });
  arrange("gradebook"); arrange("progress");
  function update() {
    fetch(url, {headers: {"Accept": "application/json"}}).then(function (r) {
      if (!r.ok) { throw new Error(r.status); }
      return r.json();
    }).then(function (t) {
      fill("gradebook", t.gradebook); fill("progress", t.progress);
      document.getElementById("counts").textContent = t.counts_text;
    }).catch(function () { status.textContent = status.dataset.failed; });
  }
  function schedule() { timer = paused ? null : setInterval(update, seconds * 1000); }
  button.hidden = false;
  status.textContent = status.dataset.on;
  button.addEventListener("click", function () {
    paused = !paused;
    if (timer) { clearInterval(timer); }
    button.textContent = paused ? button.dataset.resume : button.dataset.pause;
    status.textContent = paused ? status.dataset.off : status.dataset.on;
    if (!paused) { update(); }
    schedule();
  });
  schedule();
})();
