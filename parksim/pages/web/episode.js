// An episode's page (parksim/pages/EpisodePage.h): the verdict on top, the replay (replay.js)
// with its scrubber and play/pause, and uPlot plots over the same time axis: position and
// heading error against the tolerance, commanded and measured wheel speeds, the estimate's
// error under a realism, contacts marked. A click on a plot moves the replay there; the
// replay's time is a line on every plot.
'use strict';

(function (P) {
  const el = P.el;
  const DEG = 180 / Math.PI;

  function header(data) {
    const v = data.verdict;
    const m = data.metrics || {};
    const tol = data.tolerance || {};
    const facts = [];
    const fact = (name, value) => facts.push(el('dt', { text: name }), el('dd', { text: value }));
    if (data.metrics) {
      fact('tracking error', 'max ' + P.mm(m.max_pos_err_m) + ' (tolerance ' +
        P.mm(tol.max_pos_err_m) + '), rms ' + P.mm(m.rms_pos_err_m));
      fact('at the goal', P.mm(m.goal_pos_err_m) + ' / ' + P.fmt(m.goal_heading_err_deg, 3) +
        ' deg (tolerance ' + P.mm(tol.goal_pos_err_m) + ' / ' + P.fmt(tol.goal_heading_err_deg) +
        ' deg; the world\'s goal ' + P.mm(data.goal.position_tolerance_m) + ' / ' +
        P.fmt(data.goal.heading_tolerance_rad * DEG) + ' deg)');
      fact('contacts', String(m.contacts) + ' (at most ' + tol.max_contacts + ')' +
        (m.contact_bodies && m.contact_bodies.length ? ': ' + m.contact_bodies.join(', ') : ''));
      fact('parked robots moved', 'up to ' + P.mm(m.max_parked_displacement_m) +
        ' (tolerance ' + P.mm(tol.max_parked_displacement_m) + ')');
      fact('simulated', P.fmt(m.sim_time_s, 4) + ' s, ' + m.steps + ' steps, ' + m.tracking +
        ' loop, realism ' + m.realism + (m.realism !== 'ideal' ? ' (noise seed ' + m.noise_seed + ')' : ''));
    }
    const ps = data.plan_summary;
    if (ps) {
      fact('plan', [ps.planner, ps.steering, 'seed ' + ps.seed, ps.status,
        ps.duration_s !== undefined ? P.fmt(ps.duration_s, 4) + ' s' : null,
        ps.path_length_m !== undefined ? P.fmt(1e3 * ps.path_length_m, 4) + ' mm' : null,
        ps.cusps !== undefined ? ps.cusps + ' cusps' : null].filter((s) => s !== null && s !== undefined).join(', '));
    }
    if (data.realisations && data.realisations.count > 1) {
      fact('realisations', data.realisations.met + ' of ' + data.realisations.count +
        ' met their tolerance; shown: the first');
    }
    fact('world', data.world_file);
    return el('header', {},
      el('h1', {}, 'Episode ', el('span', { text: data.scenario }), ' ', P.badge(v.status)),
      el('p', { class: 'verdict' + (v.met ? ' met' : ' failed'), id: 'verdict',
        text: v.met ? 'met its tolerance' : v.reason || v.status }),
      el('dl', { class: 'facts' }, facts));
  }

  // A series' value in the hover legend: three significant digits and its unit (uPlot's own
  // keeps three decimals, and 0.00029 mm read "0"); `raw`, when given, the values shown in
  // place of those drawn (a log plot draws them floored).
  function legendValue(unit, raw) {
    return (u, v, si, i) => {
      const x = raw && i !== null && i !== undefined ? raw[i] : v;
      return x === null || x === undefined || Number.isNaN(x) ? '--' : P.fmt(x, 3) + ' ' + unit;
    };
  }

  // uPlot options for one plot over time: `yLabel` names the left axis's quantity and unit
  // (one unit per axis); `log`: a logarithmic y axis.
  function plotOptions(title, yLabel, series, width, contacts, onPick, log) {
    return {
      title,
      width,
      height: 170,
      cursor: { sync: { key: 'episode' }, drag: { x: true, y: false } },
      scales: { x: { time: false }, y: log ? { distr: 3 } : {} },
      axes: [{ label: 't (s)' },
        { label: yLabel, size: 60, values: (u, splits) => splits.map((v) => P.fmt(v, 3)) }],
      series: [{ label: 't', value: legendValue('s') }, ...series],
      hooks: {
        ready: [(u) => {
          u.over.addEventListener('click', (e) => onPick(u.posToVal(e.offsetX, 'x')));
          const marker = el('div', { class: 'time-marker' });
          u.over.append(marker);
          u.parksimMarker = marker;
        }],
        draw: [(u) => {
          // Contact events: red lines where they began.
          const ctx = u.ctx;
          ctx.save();
          ctx.strokeStyle = '#cf222e';
          ctx.lineWidth = 1.5 * devicePixelRatio;
          for (const c of contacts) {
            const x = u.valToPos(c.t_s, 'x', true);
            ctx.beginPath();
            ctx.moveTo(x, u.bbox.top);
            ctx.lineTo(x, u.bbox.top + u.bbox.height);
            ctx.stroke();
          }
          ctx.restore();
        }],
      },
    };
  }

  function plots(data, root, onPick) {
    const c = data.record.columns;
    const col = (name) => (c[name] ? P.column(c[name]) : null);
    const t = col('t');
    const scaled = (a, f) => Float64Array.from(a, (x) => x * f);
    const constant = (v) => new Float64Array(t.length).fill(v);
    const tol = data.tolerance || {};
    const contacts = data.contacts || [];
    const box = el('section', { class: 'plots', id: 'plots' });
    root.append(box);
    const width = Math.max(320, box.clientWidth - 8);
    // Errors far below the tolerance and the tolerance itself both show on a log scale; its
    // floor, 0.1 um, stands for anything smaller (a log axis has no zero).
    const floored = (a) => Float64Array.from(a, (x) => Math.max(1e-4, 1e3 * x));
    const pos = col('pos_err');
    const posMm = scaled(pos, 1e3);
    // Each plot: title, left axis label, series (each with its unit), values, log scale.
    const specs = [
      ['Position error against the plan (log scale)', 'error (mm)',
        [{ label: 'position error', stroke: '#0969da', width: 1.5, value: legendValue('mm', posMm) },
          { label: 'tolerance', stroke: '#cf222e', dash: [6, 4], value: legendValue('mm') }],
        [floored(pos), constant(1e3 * tol.max_pos_err_m)], true],
      ['Heading error against the plan', 'error (deg)',
        [{ label: 'heading error', stroke: '#8250df', width: 1.5, value: legendValue('deg') }],
        [scaled(col('heading_err'), DEG)]],
      ['Wheel speeds', 'speed (rad/s)',
        [{ label: 'left commanded', stroke: '#1f6feb', dash: [5, 3], value: legendValue('rad/s') },
          { label: 'left measured', stroke: '#1f6feb', value: legendValue('rad/s') },
          { label: 'right commanded', stroke: '#d4610b', dash: [5, 3], value: legendValue('rad/s') },
          { label: 'right measured', stroke: '#d4610b', value: legendValue('rad/s') }],
        [col('omega_left_cmd'), col('omega_left'), col('omega_right_cmd'), col('omega_right')]],
    ];
    if (c.est_pos_err) {
      // Two units, two axes: the position on the left, the heading on the right.
      specs.push(['Estimate against the truth: position (left axis), heading (right axis)',
        'position error (mm)',
        [{ label: 'position error', stroke: '#0b7285', width: 1.5, value: legendValue('mm') },
          { label: 'heading error', stroke: '#a40e26', scale: 'deg', value: legendValue('deg') }],
        [scaled(col('est_pos_err'), 1e3), scaled(col('est_heading_err'), DEG)]]);
    }
    const made = [];
    for (const [title, yLabel, series, values, log] of specs) {
      const opts = plotOptions(title, yLabel, series, width, contacts, onPick, log);
      if (series.some((s) => s.scale === 'deg')) {
        opts.axes.push({ scale: 'deg', side: 1, grid: { show: false }, size: 60, label: 'heading error (deg)',
          values: (u, splits) => splits.map((v) => P.fmt(v, 3)) });
      }
      made.push(new uPlot(opts, [t, ...values], box));
    }
    return made;
  }

  function controls(replay, onTime) {
    const play = el('button', { class: 'play', id: 'play', title: 'play / pause (space)', text: 'Play' });
    const speed = el('select', { id: 'speed', title: 'playback speed' },
      [0.1, 0.25, 0.5, 1, 2, 5, 10, 20].map((s) => el('option', { value: s, selected: s === 1, text: s + 'x' })));
    const scrub = el('input', { type: 'range', id: 'scrubber', min: 0, max: replay.rows - 1, step: 1, value: 0 });
    const clock = el('span', { class: 'clock', id: 'clock' });
    const follow = el('label', {}, el('input', { type: 'checkbox', id: 'follow' }), ' follow the robot');
    const fit = el('button', { text: 'Fit', title: 'show the whole lot (or double-click the lot)' });
    let playing = false;
    let last = 0;
    const update = () => {
      scrub.value = replay.index;
      const s = replay.state();
      clock.textContent = 't = ' + s.t.toFixed(3) + ' s of ' + replay.duration().toFixed(3) + ' s';
      onTime(s.t);
    };
    const step = (now) => {
      if (!playing) return;
      const dt = (now - last) / 1000;
      last = now;
      const t = replay.state().t + dt * Number(speed.value);
      replay.seek(t);
      update();
      if (replay.index >= replay.rows - 1) stop();
      else requestAnimationFrame(step);
    };
    const start = () => {
      if (replay.index >= replay.rows - 1) replay.setIndex(0);
      playing = true;
      play.textContent = 'Pause';
      last = performance.now();
      requestAnimationFrame(step);
    };
    const stop = () => {
      playing = false;
      play.textContent = 'Play';
    };
    play.addEventListener('click', () => (playing ? stop() : start()));
    scrub.addEventListener('input', () => {
      replay.setIndex(Number(scrub.value));
      update();
    });
    follow.firstChild.addEventListener('change', (e) => {
      replay.follow = e.target.checked;
      replay.setIndex(replay.index);
    });
    fit.addEventListener('click', () => replay.fit());
    document.addEventListener('keydown', (e) => {
      if (e.target.tagName === 'INPUT' && e.target.type !== 'range') return;
      if (e.key === ' ') {
        e.preventDefault();
        if (playing) stop();
        else start();
      } else if (e.key === 'ArrowRight' || e.key === 'ArrowLeft') {
        e.preventDefault();
        replay.setIndex(replay.index + (e.key === 'ArrowRight' ? 1 : -1));
        update();
      }
    });
    return { box: el('div', { class: 'controls' }, play, speed, scrub, clock, follow, fit), update };
  }

  function contactList(data, seek) {
    if (!data.contacts || data.contacts.length === 0) return null;
    return el('section', { class: 'contacts' }, el('h2', { text: 'Contacts' }),
      el('ul', {}, data.contacts.map((c) => el('li', {},
        el('a', { href: '#', onclick: (e) => { e.preventDefault(); seek(c.t_s); } },
          't = ' + c.t_s.toFixed(3) + ' s'), ': ' + c.body))));
  }

  // Every measurement, lengths in mm under "_mm" keys (P.mmKey) as on the sweep's table.
  function metricsTable(data) {
    if (!data.metrics) return null;
    const row = ([k, v]) => {
      const mm = typeof v === 'number' && P.isMetresKey(k);
      return el('tr', {}, el('th', { text: mm ? P.mmKey(k) : k }),
        el('td', { text: Array.isArray(v) ? v.join(', ') : P.fmt(mm ? 1e3 * v : v, 6) }));
    };
    return el('details', { class: 'metrics' }, el('summary', { text: 'Every measurement (metrics.json; lengths in mm)' }),
      el('table', {}, el('tbody', {}, Object.entries(data.metrics).map(row))));
  }

  function main(data, root) {
    root.append(header(data));
    const stage = el('section', { class: 'replay' });
    const canvas = el('canvas', { id: 'lot', title: 'wheel: zoom, drag: pan, double-click: fit' });
    stage.append(canvas);
    root.append(stage);
    const replay = new P.Replay(canvas, data);
    replay.fit();
    window.addEventListener('resize', () => replay.fit());
    window.parksimReplay = replay;
    if (!replay.track) {
      stage.append(el('p', { class: 'note', text: 'Nothing was driven: ' + (data.verdict.reason || 'no plan') }));
      return;
    }
    let made = [];
    const onTime = (t) => {
      for (const u of made) {
        if (u.parksimMarker) u.parksimMarker.style.left = u.valToPos(t, 'x') + 'px';
      }
    };
    const ctl = controls(replay, onTime);
    stage.append(ctl.box, P.replayLegend(replay));
    if (!data.record) {
      stage.append(el('p', { class: 'note', text: 'Not driven: the replay shows the plan.' }));
    } else if (data.record.stride > 1) {
      stage.append(el('p', { class: 'note', text: 'A long record: this page holds every ' +
        data.record.stride + 'th row of it (and the last); the record file has them all.' }));
    }
    const seek = (t) => {
      replay.seek(t);
      ctl.update();
    };
    if (data.record) made = plots(data, root, seek);
    window.parksimPlots = made;
    const list = contactList(data, seek);
    if (list) root.append(list);
    const details = metricsTable(data);
    if (details) root.append(details);
    ctl.update();
  }

  P.start(main);
})(parksim);
