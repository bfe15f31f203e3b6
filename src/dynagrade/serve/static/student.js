/* The student page, enhanced: a live preview of how each answer reads as it is typed (the
   page itself says how the answers it shows read, so nothing is asked on load), drafts saved as
   the student types (and a warning before leaving while one is not saved yet), times in
   the reader's own zone, a countdown to the close or to the end of a timed exam's time,
   the submit button disabled while saving and the focus on the summary a submit ends
   on. Without this script the page works as plain forms. */
(function () {
  "use strict";
  var main = document.getElementById("main");
  if (!main) return;
  var token = main.dataset.token, base = main.dataset.base, lang = main.dataset.lang;
  var headers = {"Authorization": "Bearer " + token, "Content-Type": "application/json"};
  var pending = {}, inFlight = 0;

  function post(path, method, body, keepalive) {
    return fetch(base + "/api/v1/" + path, {method: method, headers: headers,
      body: JSON.stringify(body), keepalive: !!keepalive});
  }

  function partValue(form, name) {
    var boxes = form.querySelectorAll('[name="answer.' + name + '"]');
    if (boxes.length === 1 && boxes[0].type !== "radio" && boxes[0].type !== "checkbox") {
      return boxes[0].value;
    }
    var picked = [];
    boxes.forEach(function (box) { if (box.checked) picked.push(box.value); });
    return picked.join(", ");
  }

  /* -- drafts ------------------------------------------------------------------------ */
  function saveDrafts(form, keepalive) {
    var exercise = form.dataset.exercise, parts = pending[exercise];
    if (!parts) return Promise.resolve();
    delete pending[exercise];
    var answers = {};
    Object.keys(parts).forEach(function (name) { answers[name] = partValue(form, name); });
    inFlight++;
    return post("drafts", "PUT", {exercise: exercise, answers: answers}, keepalive)
      .then(function (r) { if (!r.ok && r.status !== 403) throw r; })
      .catch(function () {  /* not saved: keep it pending, try again later */
        pending[exercise] = Object.assign(pending[exercise] || {}, parts); })
      .finally(function () { inFlight--; });
  }

  function flushAll(keepalive) {
    var saving = [];
    document.querySelectorAll("form.answers").forEach(function (form) {
      clearTimeout(form._draftTimer);
      saving.push(saveDrafts(form, keepalive));
    });
    return Promise.all(saving);
  }

  window.addEventListener("beforeunload", function (event) {
    if (Object.keys(pending).length || inFlight) {
      flushAll(true);
      event.preventDefault();
      event.returnValue = main.dataset.unsaved;
      return main.dataset.unsaved;
    }
  });

  /* -- each form: preview, drafts, submit ---------------------------------------------- */
  document.querySelectorAll("form.answers").forEach(function (form) {
    var exercise = form.dataset.exercise, practice = form.dataset.practice || null;
    var submitting = false;

    function changed(name) {
      if (practice) return;  /* a practice draw keeps no drafts */
      pending[exercise] = pending[exercise] || {};
      pending[exercise][name] = true;
      clearTimeout(form._draftTimer);
      form._draftTimer = setTimeout(function () { saveDrafts(form); }, 800);
    }

    form.querySelectorAll("input[data-part]").forEach(function (input) {
      var name = input.dataset.part, timer = null, asked = 0;
      var out = document.getElementById(input.id + "--preview");
      function preview() {
        var mine = ++asked;
        if (!input.value.trim()) { out.textContent = ""; input.removeAttribute("aria-invalid"); return; }
        post("preview", "POST", {exercise: exercise, part: name, answer: input.value,
                                 practice: practice})
          .then(function (r) { return r.json().then(function (j) { j.busy = r.status === 503; return j; }); })
          .then(function (j) {
            if (mine !== asked) return;
            if (j.busy) {  /* previews are shed first when the server is busy: no verdict on the box */
              out.textContent = j.detail || "";
              out.classList.remove("bad");
              input.removeAttribute("aria-invalid");
              return;
            }
            out.textContent = j.message || j.detail || "";
            out.classList.toggle("bad", !j.readable);
            if (j.readable) input.removeAttribute("aria-invalid");
            else input.setAttribute("aria-invalid", "true");
            if (j.formula) {
              var shown = document.createElement("span");
              shown.className = "formula";
              shown.innerHTML = " " + j.formula;
              out.appendChild(shown);
            }
          })
          .catch(function () {});
      }
      input.addEventListener("input", function () {
        clearTimeout(timer);
        timer = setTimeout(preview, 250);
        if (!input.readOnly) changed(name);
      });
      /* no preview on load: the page carries how each filled box reads */
    });

    form.querySelectorAll("fieldset[data-choice]").forEach(function (set) {
      set.addEventListener("change", function () { changed(set.dataset.choice); });
    });

    form.addEventListener("submit", function (event) {
      event.preventDefault();
      if (submitting) return;
      submitting = true;
      var button = form.querySelector("button[type=submit]");
      if (button) {
        button.disabled = true;
        button.setAttribute("aria-busy", "true");
        button.textContent = main.dataset.saving;
      }
      var timeout = new Promise(function (done) { setTimeout(done, 3000); });
      Promise.race([flushAll(false), timeout]).then(function () { form.submit(); });
    });
  });

  /* -- times in the reader's zone ---------------------------------------------------- */
  var format;
  try {
    format = new Intl.DateTimeFormat(lang, {year: "numeric", month: "short", day: "numeric",
      hour: "2-digit", minute: "2-digit", timeZoneName: "short"});
  } catch (e) { format = null; }
  if (format) {
    document.querySelectorAll("time[data-local]").forEach(function (time) {
      var moment = new Date(time.getAttribute("datetime"));
      if (!isNaN(moment)) time.textContent = format.format(moment);
    });
  }

  /* -- the countdown to the close (or the end of a timed exam's time) ----------------- */
  var clock = document.getElementById("countdown");
  if (clock) {
    var closes = new Date(clock.dataset.closes).getTime(), warning = document.getElementById("warning");
    var warned = Infinity, steps = [10, 5, 1];
    clock.hidden = false;
    var tick = function () {
      var left = Math.max(0, Math.round((closes - Date.now()) / 1000));
      if (left <= 0) {
        clock.textContent = clock.dataset.closed;
        warning.hidden = true;
        document.querySelectorAll("form.answers button[type=submit]").forEach(function (b) {
          b.disabled = true; });
        clearInterval(timer);
        return;
      }
      /* whole minutes: the text changes about once a minute, so a screen reader that
         reads the page finds it steady (it is no live region; the warnings are) */
      var h = Math.floor(left / 3600), m = Math.floor(left % 3600 / 60);
      var text = h || m ? (h ? h + " h " : "") + m + " min" : clock.dataset.soon;
      text = clock.dataset.left.replace("{time}", text);
      if (clock.textContent !== text) clock.textContent = text;
      steps.forEach(function (step) {
        if (left <= step * 60 && step < warned) {
          warned = step;
          warning.textContent = warning.dataset.warn.replace("{minutes}", String(step));
          warning.hidden = false;
        }
      });
    };
    var timer = setInterval(tick, 1000);
    tick();
  }

  /* -- after a submit: the focus on its summary -------------------------------------- */
  var status = document.getElementById("status");
  if (status) status.focus();
})();
