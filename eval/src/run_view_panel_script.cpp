// The step panel of run_view's pages (ES5, no modules, no network): sxRunPanel(data, hooks) shows the
// selected step's number, scans, time, verdict, trust, recovery, reason, termination and error; lists
// the marked steps (not trusted, not converged, recovered) or the largest errors, 1000 rows at a
// time; and moves to the previous / next entry of the list (buttons, keys P / N) or to a step by its
// number. Every text goes in through textContent. hooks.select(i, focus) tells the viewer.
#include "run_view_script.hpp"

namespace sextant::detail {

const char* run_view_panel_script() {
  return R"JS(function sxRunPanel(data, hooks) {
  'use strict';
  var steps = data.steps, texts = steps.texts, noun = steps.name;
  var verdictNames = ['trusted', 'recovered', 'untrusted', 'not converged', 'no verdict'];
  var box = document.getElementById('sx-step'), list = document.getElementById('sx-list');
  var kind = document.getElementById('sx-list-kind'), current = -1, shown = [];
  var t0 = null;
  for (var s = 0; s < steps.count; ++s) if (steps.stamp[s] !== null) { t0 = steps.stamp[s]; break; }
  var epoch = t0 !== null && Math.abs(t0) > 1e5;  // Unix stamps: times from the first one
  var assessed = false;  // any verdict at all (a trajectory from a file has none: no verdict column)
  for (var a = 0; a < steps.count; ++a) if (steps.verdict[a] !== 4) { assessed = true; break; }

  function el(tag, text, cls) {
    var e = document.createElement(tag);
    if (text !== undefined && text !== null) e.textContent = text;
    if (cls) e.className = cls;
    return e;
  }
  function text(field, i) { return texts[steps[field][i]]; }
  function time(i) {
    var t = steps.stamp[i];
    if (t === null) return '–';
    return epoch ? '+' + (t - t0).toFixed(2) + ' s' : t.toFixed(2) + ' s';
  }
  function error(i) {
    var m = steps.error_m[i], d = steps.error_deg[i];
    if (m === null && d === null) return '–';
    return (m === null ? '' : m.toFixed(3) + ' m') + (m !== null && d !== null ? ', ' : '') +
           (d === null ? '' : d.toFixed(2) + '°');
  }
  function title(i) {
    var t = noun + ' ' + steps.number[i];
    if (steps.from[i] < steps.to[i]) t += ' · scans ' + steps.from[i] + ' → ' + steps.to[i];
    return t;
  }
  function chip(v) { return el('span', verdictNames[v], 'sx-chip sx-v' + v); }

  function show(i) {
    box.textContent = '';
    box.appendChild(el('h2', title(i)));
    var table = el('table');
    function row(label, value) {
      if (value === '' || value === undefined) return;
      var tr = el('tr');
      tr.appendChild(el('th', label));
      var td = el('td');
      if (typeof value === 'string') td.textContent = value;
      else td.appendChild(value);
      tr.appendChild(td);
      table.appendChild(tr);
    }
    var v = steps.verdict[i];
    row('time', steps.stamp[i] === null ? '–' : time(i) + (epoch ? ' (stamp ' + steps.stamp[i].toFixed(6) + ')' : ''));
    if (v !== 4) {
      var verdict = el('span');
      verdict.appendChild(chip(v));
      if (text('trust', i)) verdict.appendChild(document.createTextNode(' trust: ' + text('trust', i)));
      row('verdict', verdict);
    }
    if (v !== 4 && text('first_trust', i) && text('first_trust', i) !== text('trust', i))
      row('first try', text('first_trust', i));
    row('recovery', text('recovery', i));
    row('reason', text('reason', i));
    if (v !== 4) row('converged', steps.converged[i] ? 'yes' : 'no');
    row('termination', text('status', i));
    row('error', error(i) === '–' ? '' : error(i) + ' (' + data.error_name + ')');
    box.appendChild(table);
  }

  // The list's entries: the marked steps in order, or the largest errors first.
  var marked = [], byError = [];
  for (var k = 0; k < steps.count; ++k) {
    if (steps.verdict[k] >= 1 && steps.verdict[k] <= 3) marked.push(k);
    if (steps.error_m[k] !== null) byError.push(k);
  }
  byError.sort(function (a, b) { return steps.error_m[b] - steps.error_m[a]; });
  byError = byError.slice(0, 100);
  var kinds = [];
  if (marked.length || !byError.length) kinds.push(['marked', 'marked ' + noun + 's: ' + marked.length + ' (not trusted, recovered)']);
  if (byError.length) kinds.push(['errors', 'the ' + byError.length + ' largest errors']);
  kinds.forEach(function (k) {
    var o = el('option', k[1]);
    o.value = k[0];
    kind.appendChild(o);
  });

  function fill(limit) {
    shown = kind.value === 'errors' ? byError : marked;
    list.textContent = '';
    if (!shown.length) {
      list.appendChild(el('p', 'No ' + noun + ' is marked: every one is trusted as the matcher returned it.', 'sx-hint'));
      return;
    }
    var table = el('table'), head = el('tr');
    (assessed ? [noun, 'time', 'verdict', 'error'] : [noun, 'time', 'error']).forEach(function (h) {
      head.appendChild(el('th', h));
    });
    table.appendChild(head);
    var n = Math.min(shown.length, limit);
    for (var r = 0; r < n; ++r) {
      var i = shown[r], tr = el('tr');
      tr.setAttribute('data-step', i);
      tr.appendChild(el('td', String(steps.number[i])));
      tr.appendChild(el('td', time(i)));
      if (assessed) {
        var td = el('td');
        td.appendChild(chip(steps.verdict[i]));
        tr.appendChild(td);
      }
      tr.appendChild(el('td', error(i)));
      table.appendChild(tr);
      var why = text('reason', i);
      if (why) {
        var tw = el('tr'), cell = el('td', why, 'sx-why');
        cell.colSpan = assessed ? 4 : 3;
        tw.setAttribute('data-step', i);
        tw.appendChild(cell);
        table.appendChild(tw);
      }
    }
    list.appendChild(table);
    if (n < shown.length) {
      var more = el('button', 'show all ' + shown.length);
      more.type = 'button';
      more.addEventListener('click', function () { fill(Infinity); });
      list.appendChild(more);
    }
    mark();
  }
  function mark() {
    var rows = list.querySelectorAll('tr[data-step]');
    for (var r = 0; r < rows.length; ++r)
      rows[r].className = parseInt(rows[r].getAttribute('data-step'), 10) === current ? 'sx-selected' : '';
  }
  function select(i, focus) {
    if (i < 0 || i >= steps.count) return;
    current = i;
    show(i);
    mark();
    var row = list.querySelector('tr.sx-selected');
    if (row && row.scrollIntoView) row.scrollIntoView({block: 'nearest'});
    if (hooks.select) hooks.select(i, focus);
  }
  function move(by) {
    if (!shown.length) return;
    var at = shown.indexOf(current), next;
    if (at >= 0) next = at + by;
    else if (current < 0 || kind.value === 'errors') next = by > 0 ? 0 : shown.length - 1;
    else {  // the marked steps are in order: the first after the selected one, or the last before it
      next = 0;
      while (next < shown.length && shown[next] < current) ++next;
      if (by < 0) --next;
    }
    select(shown[Math.max(0, Math.min(shown.length - 1, next))], true);
  }
  list.addEventListener('click', function (e) {
    for (var t = e.target; t && t !== list; t = t.parentNode)
      if (t.getAttribute && t.getAttribute('data-step') !== null) return select(parseInt(t.getAttribute('data-step'), 10), true);
  });
  kind.addEventListener('change', function () { fill(1000); });
  document.getElementById('sx-prev').addEventListener('click', function () { move(-1); });
  document.getElementById('sx-next').addEventListener('click', function () { move(1); });
  var go = document.getElementById('sx-goto');
  function byNumber(number) {
    for (var i = 0; i < steps.count; ++i) if (steps.number[i] === number) return i;
    return -1;
  }
  go.addEventListener('change', function () { select(byNumber(parseInt(go.value, 10)), true); });
  window.addEventListener('keydown', function (e) {
    if (e.ctrlKey || e.altKey || e.metaKey || e.target.tagName === 'INPUT' || e.target.tagName === 'SELECT') return;
    if (e.key === 'n' || e.key === 'N') move(1);
    if (e.key === 'p' || e.key === 'P') move(-1);
  });
  fill(1000);
  return {select: select, byNumber: byNumber, current: function () { return current; }};
}
)JS";
}

}  // namespace sextant::detail
