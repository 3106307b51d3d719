(function () {
  'use strict';
  var store = JSON.parse(document.getElementById('sb-images').textContent);
  var cardStore = null;   // parsed on the first card opened
  var groupStore = null;  // the cards several failing cells share, likewise
  // Puts a lazily stored card into `el` (a detail cell or a closed failure card).
  function fill(el) {
    if (el.dataset.group !== undefined) {
      if (!groupStore) groupStore = JSON.parse(document.getElementById('sb-groups').textContent);
      el.insertAdjacentHTML('beforeend', groupStore[+el.dataset.group]);
      delete el.dataset.group;
      return;
    }
    if (el.dataset.card === undefined) return;
    if (!cardStore) cardStore = JSON.parse(document.getElementById('sb-cards').textContent);
    el.insertAdjacentHTML('beforeend', cardStore[+el.dataset.card]);
    delete el.dataset.card;
  }
  var body = document.body;
  var table = document.getElementById('cells');
  var timer = null;

  // Readiness for people and for tests: every <img> that has a source is complete and decoded.
  function check() {
    var imgs = Array.prototype.slice.call(document.querySelectorAll('img[src]'));
    if (imgs.some(function (i) { return !i.complete; })) { timer = setTimeout(check, 25); return; }
    var ok = imgs.filter(function (i) { return i.naturalWidth > 0; }).length;
    body.setAttribute('data-images-total', imgs.length);
    body.setAttribute('data-images-decoded', ok);
    body.setAttribute('data-images-ready', ok === imgs.length ? 'all' : 'broken');
  }
  function settle() {
    body.setAttribute('data-images-ready', 'pending');
    clearTimeout(timer);
    timer = setTimeout(check, 0);
  }
  function show(root) {
    var imgs = root.querySelectorAll('img[data-img]:not([src]), img[data-file]:not([src])');
    if (!imgs.length) return;
    Array.prototype.forEach.call(imgs, function (img) {
      if (img.dataset.img) { img.src = store[img.dataset.img]; return; }
      img.onerror = function () {
        var d = document.createElement('div');
        d.className = 'missing';
        d.textContent = 'not embedded, not found next to the report: ' + img.title;
        img.replaceWith(d);
        settle();
      };
      img.src = img.dataset.file;
    });
    settle();
  }
  function toggle(tbody, open) {
    var detail = tbody.rows[1];
    if (open === undefined) open = detail.hidden;
    detail.hidden = !open;
    if (open) { fill(detail.cells[0]); show(detail); }
  }

  // A card's reference | render | error: zoom applies one transform to all three (so the
  // same pixel stays under the eye in each), flicker shows the reference in the render's place.
  function trioOf(el) { return el.closest('.trio'); }
  function setZoom(trio, s, tx, ty) {
    var vp = trio.querySelector('.vp'), w = vp ? vp.clientWidth : 0, h = vp ? vp.clientHeight : 0;
    s = Math.min(32, Math.max(1, s));
    tx = Math.min(0, Math.max(w - w * s, tx));   // the image keeps covering its viewport
    ty = Math.min(0, Math.max(h - h * s, ty));
    trio.dataset.zoom = s === 1 ? '1 0 0' : s + ' ' + tx + ' ' + ty;
    applyZoom(trio);
  }
  function applyZoom(trio) {
    var z = (trio.dataset.zoom || '1 0 0').split(' ');
    var t = z[0] === '1' ? '' : 'translate(' + z[1] + 'px, ' + z[2] + 'px) scale(' + z[0] + ')';
    Array.prototype.forEach.call(trio.querySelectorAll('.vp img'), function (img) { img.style.transform = t; });
  }
  // A shared card's "show": that cell's images in the trio, at the same zoom.
  function showCell(button) {
    var card = button.closest('.card'), trio = card.querySelector('.trio');
    var t = card.querySelector('template[data-cell="' + button.dataset.cell + '"]');
    if (!trio || !t) return;
    trio.querySelector('.imgs').innerHTML = t.innerHTML;
    delete trio.dataset.showing;
    show(trio);
    applyZoom(trio);
    Array.prototype.forEach.call(card.querySelectorAll('.group li'), function (li) {
      li.classList.toggle('shown', li.contains(button));
    });
  }
  // Zooms by `factor` keeping the point (x, y) of the viewport where it is.
  function zoomAt(img, factor, x, y) {
    var trio = trioOf(img), z = (trio.dataset.zoom || '1 0 0').split(' ').map(Number);
    var s = Math.min(32, Math.max(1, z[0] * factor)), k = s / z[0];
    setZoom(trio, s, x - (x - z[1]) * k, y - (y - z[2]) * k);
  }
  function pointIn(img, e) {
    var r = img.parentNode.getBoundingClientRect();
    return [e.clientX - r.left, e.clientY - r.top];
  }
  function flicker(trio) {
    var render = trio.querySelector('figure[data-role="render"] img');
    var ref = trio.querySelector('figure[data-role="reference"] img');
    if (!render || !ref || !ref.getAttribute('src')) return;
    var toReference = trio.dataset.showing !== 'reference';
    if (!render.dataset.own) render.dataset.own = render.getAttribute('src');
    render.src = toReference ? ref.getAttribute('src') : render.dataset.own;
    trio.dataset.showing = toReference ? 'reference' : 'render';
    var caption = render.closest('figure').querySelector('figcaption');
    if (caption) caption.textContent = toReference ? 'reference (flicker)' : 'render';
    settle();
  }
  document.addEventListener('wheel', function (e) {
    var img = e.target.closest && e.target.closest('.trio .vp img');
    if (!img) return;
    e.preventDefault();
    var p = pointIn(img, e);
    zoomAt(img, e.deltaY < 0 ? 1.25 : 0.8, p[0], p[1]);
  }, { passive: false });

  document.addEventListener('click', function (e) {
    var view = e.target.closest('.trio .vp img');
    if (view) { var p = pointIn(view, e); zoomAt(view, e.shiftKey ? 0.5 : 2, p[0], p[1]); return; }
    var pick = e.target.closest('.group button.pick');
    if (pick) { showCell(pick); return; }
    var button = e.target.closest('.trio button');
    if (button) {
      if (button.classList.contains('flicker')) flicker(trioOf(button));
      else setZoom(trioOf(button), 1, 0, 0);
      return;
    }
    var img = e.target.closest('figure img');
    if (img) { img.classList.toggle('zoom'); return; }
    var row = e.target.closest('#cells tr.row');
    if (row && !e.target.closest('a')) toggle(row.parentNode);
    var jump = e.target.closest('a.jump');
    if (jump) {
      var target = document.getElementById(jump.getAttribute('href').slice(1));
      if (target) {
        if (collapsed) { filter.value = target.dataset.id; apply(); }   // just this row of a big table
        target.hidden = false;
        toggle(target, true);
      }
    }
  });
  document.addEventListener('keydown', function (e) {
    if (e.key !== 'Enter' && e.key !== ' ') return;
    var row = e.target.closest && e.target.closest('#cells tr.row');
    if (row) { e.preventDefault(); toggle(row.parentNode); }
    var th = e.target.closest && e.target.closest('#cells th');
    if (th) { e.preventDefault(); sortBy(th); }
  });
  Array.prototype.forEach.call(document.querySelectorAll('details.fc'), function (d) {
    if (d.open) { fill(d); show(d); }
    d.addEventListener('toggle', function () { if (d.open) { fill(d); show(d); } });
  });

  // Sorting: numbers by data-v (unmeasured cells last either way), text by content; ties
  // keep the run's order.
  function sortBy(th, desc) {
    var col = th.cellIndex, numeric = th.dataset.type === 'num';
    if (desc === undefined) desc = th.getAttribute('aria-sort') === 'ascending';
    var bodies = Array.prototype.slice.call(table.tBodies);
    bodies.sort(function (a, b) {
      var x = a.rows[0].cells[col], y = b.rows[0].cells[col], c;
      if (numeric) {
        var xm = x.dataset.v === '', ym = y.dataset.v === '';
        if (xm || ym) c = xm === ym ? 0 : (xm ? 1 : -1);
        else {
          var xv = parseFloat(x.dataset.v), yv = parseFloat(y.dataset.v);
          c = xv < yv ? -1 : xv > yv ? 1 : 0;
          if (desc) c = -c;
        }
      } else {
        c = x.textContent.localeCompare(y.textContent);
        if (desc) c = -c;
      }
      return c || (+a.dataset.i - +b.dataset.i);
    });
    var frag = document.createDocumentFragment();
    bodies.forEach(function (b) { frag.appendChild(b); });
    table.appendChild(frag);
    Array.prototype.forEach.call(table.tHead.rows[0].cells, function (h) { h.removeAttribute('aria-sort'); });
    th.setAttribute('aria-sort', desc ? 'descending' : 'ascending');
    body.setAttribute('data-sorted', th.dataset.key + (desc ? ':desc' : ''));
  }
  Array.prototype.forEach.call(table.tHead.rows[0].cells, function (th) {
    th.addEventListener('click', function () { sortBy(th); });
  });

  // Filtering by text and status.
  var filter = document.getElementById('filter'), status = document.getElementById('status');
  var collapsed = table.dataset.collapsed === '1', note = document.getElementById('collapsed');
  function apply() {
    var text = filter.value.toLowerCase(), st = status.value, shown = 0;
    if (text || st) collapsed = false;   // a big table shows rows once asked for some
    Array.prototype.forEach.call(table.tBodies, function (b) {
      var k = b.classList.contains('pass') ? 'pass' : b.classList.contains('fail') ? 'fail'
            : b.classList.contains('known') ? 'known' : b.classList.contains('skipped') ? 'skipped' : 'error';
      var ok = (!st || st === k || (st === 'failing' && k !== 'pass' && k !== 'skipped')) &&
               (!text || b.rows[0].textContent.toLowerCase().indexOf(text) >= 0 ||
                (b.dataset.id || '').toLowerCase().indexOf(text) >= 0);
      b.hidden = collapsed || !ok;
      shown += !b.hidden;
    });
    document.getElementById('shown').textContent = shown + ' of ' + table.tBodies.length + ' shown';
    if (note) note.hidden = !collapsed;
  }
  filter.addEventListener('input', apply);
  status.addEventListener('change', apply);
  if (note) document.getElementById('showall').addEventListener('click', function () { collapsed = false; apply(); });
  document.getElementById('expand').addEventListener('click', function () {
    Array.prototype.forEach.call(table.tBodies, function (b) { if (!b.hidden) toggle(b, true); });
  });
  document.getElementById('collapse').addEventListener('click', function () {
    Array.prototype.forEach.call(table.tBodies, function (b) { toggle(b, false); });
  });

  // URL fragment: #expand-all&sort=max_abs:desc&status=failing&filter=text. Read on load,
  // on every change (back/forward) and from the matrix links, which also scroll to the table.
  function options(hash) {
    var expand = false, filtered = false;
    hash.replace(/^#/, '').split('&').forEach(function (opt) {
      if (!opt) return;
      var eq = opt.indexOf('='), key = eq < 0 ? opt : opt.slice(0, eq), value = eq < 0 ? '' : decodeURIComponent(opt.slice(eq + 1));
      if (key === 'filter') { filter.value = value; filtered = true; }
      if (key === 'status') status.value = value;
      if (key === 'expand-all') { expand = true; collapsed = false; }
      if (key === 'sort') {
        var parts = value.split(':'), th = table.querySelector('th[data-key="' + parts[0] + '"]');
        if (th) sortBy(th, parts[1] === 'desc');
      }
    });
    apply();
    if (expand) Array.prototype.forEach.call(table.tBodies, function (b) { if (!b.hidden) toggle(b, true); });
    return filtered;
  }
  document.addEventListener('click', function (e) {
    var a = e.target.closest('a.mxl');
    if (!a) return;
    e.preventDefault();
    try { history.pushState(null, '', a.getAttribute('href')); } catch (err) { /* some file: pages refuse */ }
    options(a.getAttribute('href'));
    document.getElementById('all').scrollIntoView();
  });
  window.addEventListener('hashchange', function () {
    if (options(location.hash)) document.getElementById('all').scrollIntoView();
  });
  if (options(location.hash)) document.getElementById('all').scrollIntoView();
  settle();
})();
