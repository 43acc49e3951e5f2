// The gallery's index (hbc._gallery_site writes its data into #gallery-data): one row per mesh,
// sorted by a click on any column's head (again: the other way), kept by the text filter (name,
// tags, error), the tag selects (model, mesher, cell types, --tags columns) and the range boxes of
// the numeric columns ("a..b", ">a", "<b", "a"). body[data-state] is "ready" once drawn.
(function () {
  'use strict';
  const data = JSON.parse(document.getElementById('gallery-data').textContent);
  const cols = data.columns;
  const tbody = document.querySelector('#gallery tbody');
  const state = { text: '', tags: {}, ranges: {}, sort: null, dir: 1 };

  function fmt(v, c) {
    if (v === null || v === undefined || v === '') return '–';
    if (typeof v !== 'number') return String(v);
    if (c.format === 'int' && Number.isInteger(v)) return v.toLocaleString('en').replace(/,/g, '\u2009');
    return c.format === 'ratio' || c.format === 's' ? v.toFixed(4) : String(+v.toPrecision(4));
  }

  function el(tag, props, children) {
    const e = Object.assign(document.createElement(tag), props || {});
    for (const c of children || []) e.append(c);
    return e;
  }

  function head() {
    const names = el('tr');
    const ranges = el('tr', { className: 'ranges' });
    names.append(el('th', { textContent: '' }), th('name', 'name', 'the file, below the folder given'));
    ranges.append(el('th'), el('th'));
    for (const c of cols) {
      names.append(th(c.key, c.label, c.title));
      const cell = el('th');
      if (c.kind === 'num') {
        const box = el('input', { type: 'text', placeholder: 'a..b', title: 'range: a..b, >a, <b or a' });
        box.dataset.range = c.key;
        box.addEventListener('input', () => { state.ranges[c.key] = parseRange(box.value); apply(); });
        cell.append(box);
      }
      ranges.append(cell);
    }
    names.append(th('error', 'error', 'why the mesh could not be measured'));
    ranges.append(el('th'));
    document.querySelector('#gallery thead').append(names, ranges);
  }

  function th(key, label, title) {
    const e = el('th', { textContent: label, title: title || '' });
    e.dataset.key = key;
    e.addEventListener('click', () => sortBy(key));
    return e;
  }

  function parseRange(s) {
    s = s.trim();
    if (!s) return null;
    let m;
    if ((m = s.match(/^(-?[\d.e+-]*)\s*\.\.\s*(-?[\d.e+-]*)$/))) return [m[1] === '' ? -Infinity : +m[1], m[2] === '' ? Infinity : +m[2]];
    if ((m = s.match(/^>=?\s*(-?[\d.e+-]+)$/))) return [+m[1], Infinity];
    if ((m = s.match(/^<=?\s*(-?[\d.e+-]+)$/))) return [-Infinity, +m[1]];
    return Number.isFinite(+s) ? [+s, +s] : [NaN, NaN];
  }

  function row(r) {
    const tr = el('tr', { className: r.error ? 'failed' : '' });
    tr.dataset.id = r.id;
    const pic = r.thumb ? el('img', { src: `thumbs/${r.id}.jpg`, alt: r.name, loading: 'lazy', width: 120, height: 90 })
      : el('div', { className: 'nothumb', textContent: r.error ? 'failed' : 'no thumbnail' });
    tr.append(el('td', { className: 'thumb' }, [r.viewer ? el('a', { href: `viewer.html?m=${r.id}` }, [pic]) : pic]));
    const name = r.viewer ? el('a', { href: `viewer.html?m=${r.id}`, textContent: r.name, className: 'open' })
      : el('span', { textContent: r.name });
    tr.append(el('td', { className: 'name', title: r.file }, [name]));
    for (const c of cols) {
      const v = r.values[c.key];
      const td = el('td', { className: c.kind });
      if (c.key === 'model' && v) td.append(el('a', { href: r.model_page, textContent: v, className: 'model' }));
      else td.textContent = fmt(v, c);
      tr.append(td);
    }
    tr.append(el('td', { className: 'error', textContent: r.error }));
    r.tr = tr;
    r.text = [r.name, r.error, ...cols.filter((c) => c.kind === 'tag').map((c) => r.values[c.key] || '')].join(' ').toLowerCase();
    return tr;
  }

  function tagFilters() {
    const box = document.getElementById('tag-filters');
    for (const c of cols.filter((c) => c.kind === 'tag')) {
      const words = new Set();
      for (const r of data.rows) for (const w of c.key === 'cell_kinds' ? (r.values[c.key] || '').split(' ') : [r.values[c.key] || '']) if (w) words.add(w);
      if (!words.size) continue;
      const sel = el('select', { title: c.title }, [el('option', { value: '', textContent: `${c.label}: all` })]);
      for (const w of [...words].sort()) sel.append(el('option', { value: w, textContent: w }));
      sel.dataset.tag = c.key;
      sel.addEventListener('change', () => { state.tags[c.key] = sel.value; apply(); });
      box.append(sel);
    }
  }

  function keeps(r) {
    if (state.text && !r.text.includes(state.text)) return false;
    for (const [k, w] of Object.entries(state.tags)) {
      if (!w) continue;
      const v = r.values[k] || '';
      if (k === 'cell_kinds' ? !v.split(' ').includes(w) : v !== w) return false;
    }
    for (const [k, range] of Object.entries(state.ranges)) {
      if (!range) continue;
      const v = r.values[k];
      if (typeof v !== 'number' || !(v >= range[0] && v <= range[1])) return false;
    }
    return true;
  }

  function sortBy(key) {
    state.dir = state.sort === key ? -state.dir : 1;
    state.sort = key;
    for (const e of document.querySelectorAll('thead th[data-key]'))
      if (e.dataset.key === key) e.setAttribute('aria-sort', state.dir > 0 ? 'ascending' : 'descending');
      else e.removeAttribute('aria-sort');
    const get = key === 'name' ? (r) => r.name : key === 'error' ? (r) => r.error : (r) => r.values[key];
    // Missing values last whichever the direction.
    const rows = [...data.rows].sort((a, b) => {
      const x = get(a), y = get(b);
      const mx = x === null || x === undefined || x === '', my = y === null || y === undefined || y === '';
      if (mx || my) return mx - my;
      return (typeof x === 'number' && typeof y === 'number' ? x - y : String(x).localeCompare(String(y), 'en', { numeric: true })) * state.dir;
    });
    tbody.append(...rows.map((r) => r.tr));
  }

  function apply() {
    let shown = 0;
    for (const r of data.rows) { const k = keeps(r); r.tr.hidden = !k; shown += k; }
    document.getElementById('count').textContent = `${shown} of ${data.rows.length} meshes`;
  }

  head();
  tbody.append(...data.rows.map(row));
  tagFilters();
  const text = document.getElementById('filter');
  text.addEventListener('input', () => { state.text = text.value.trim().toLowerCase(); apply(); });
  document.getElementById('clear').addEventListener('click', () => {
    text.value = ''; state.text = ''; state.tags = {}; state.ranges = {};
    for (const s of document.querySelectorAll('select[data-tag]')) s.value = '';
    for (const b of document.querySelectorAll('input[data-range]')) b.value = '';
    apply();
  });
  apply();
  document.body.dataset.state = 'ready';
})();
