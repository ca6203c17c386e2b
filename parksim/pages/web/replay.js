// An episode replayed on a canvas (parksim/pages/EpisodePage.h): the lot, its obstacles, the
// start, the goal with its tolerance and the plan drawn once per view into a back buffer; over
// it, each frame, the path driven so far, the reference pose, the estimate (under a realism),
// the robot and the contacts that have happened. The robot is where the record's row at or
// before the chosen time puts it, never interpolated. Wheel zooms, dragging pans, a double
// click fits the lot; "follow" keeps the robot in the middle.
'use strict';

(function (P) {
  function columnsOf(source, names) {
    const out = {};
    for (const [key, name] of Object.entries(names)) {
      if (source[name]) out[key] = P.column(source[name]);
    }
    return out;
  }

  // The poses a replay steps through: the record's rows, or for a plan that was not driven
  // the plan's own points.
  function trackOf(data) {
    if (data.record) {
      return columnsOf(data.record.columns, {
        t: 't', x: 'x', y: 'y', theta: 'theta', xr: 'x_ref', yr: 'y_ref', thr: 'theta_ref',
        xe: 'x_est', ye: 'y_est', the: 'theta_est', steer: 'steer',
      });
    }
    if (data.plan) return columnsOf(data.plan, { t: 't', x: 'x', y: 'y', theta: 'theta' });
    return null;
  }

  class Replay {
    constructor(canvas, data) {
      this.canvas = canvas;
      this.data = data;
      this.style = data.style;
      this.track = trackOf(data);
      this.rows = this.track ? this.track.t.length : 0;
      this.index = 0;
      this.follow = false;
      this.path = data.plan ? { x: P.column(data.plan.path.x), y: P.column(data.plan.path.y) } : null;
      this.contacts = (data.contacts || []).map((c) => ({ ...c, index: this.indexAt(c.t_s) }));
      this.back = document.createElement('canvas');
      this.view = null;
      this.listen();
    }

    // The last row at or before time t (the first row before the start).
    indexAt(t) {
      if (!this.track) return 0;
      const ts = this.track.t;
      let lo = 0;
      let hi = ts.length - 1;
      if (t <= ts[0]) return 0;
      while (lo < hi) {
        const mid = (lo + hi + 1) >> 1;
        if (ts[mid] <= t) lo = mid;
        else hi = mid - 1;
      }
      return lo;
    }

    duration() {
      return this.rows > 0 ? this.track.t[this.rows - 1] : 0;
    }

    // Where the robot is drawn now: {t, index, x, y, theta}.
    state() {
      if (!this.track) return null;
      const i = this.index;
      const tr = this.track;
      return { t: tr.t[i], index: i, x: tr.x[i], y: tr.y[i], theta: tr.theta[i] };
    }

    seek(t) {
      this.setIndex(this.indexAt(t));
    }

    setIndex(i) {
      this.index = Math.max(0, Math.min(this.rows - 1, i | 0));
      if (this.follow && this.track) {
        this.view.cx = this.track.x[this.index];
        this.view.cy = this.track.y[this.index];
        this.view.dirty = true;
      }
      this.draw();
    }

    // CSS pixels of a lot point.
    toScreen(x, y) {
      const v = this.view;
      return [v.w / 2 + (x - v.cx) * v.scale, v.h / 2 - (y - v.cy) * v.scale];
    }

    fromScreen(px, py) {
      const v = this.view;
      return [v.cx + (px - v.w / 2) / v.scale, v.cy - (py - v.h / 2) / v.scale];
    }

    // Sizes the canvas to its box and shows the whole lot.
    fit() {
      const rect = this.canvas.getBoundingClientRect();
      const w = Math.max(50, rect.width);
      const h = Math.max(50, rect.height);
      const dpr = window.devicePixelRatio || 1;
      for (const c of [this.canvas, this.back]) {
        c.width = Math.round(w * dpr);
        c.height = Math.round(h * dpr);
      }
      const lot = this.data.lot;
      const margin = 0.04 * Math.max(lot.x_max - lot.x_min, lot.y_max - lot.y_min);
      const ww = lot.x_max - lot.x_min + 2 * margin;
      const wh = lot.y_max - lot.y_min + 2 * margin;
      this.view = {
        w, h, dpr,
        scale: Math.min(w / ww, h / wh),
        cx: (lot.x_min + lot.x_max) / 2,
        cy: (lot.y_min + lot.y_max) / 2,
        dirty: true,
      };
      this.draw();
    }

    listen() {
      const c = this.canvas;
      c.addEventListener('wheel', (e) => {
        e.preventDefault();
        const [x, y] = this.fromScreen(e.offsetX, e.offsetY);
        const f = Math.exp(-e.deltaY * 0.0015);
        const v = this.view;
        v.scale *= f;
        v.cx = x - (x - v.cx) / f;
        v.cy = y - (y - v.cy) / f;
        v.dirty = true;
        this.draw();
      }, { passive: false });
      let drag = null;
      c.addEventListener('pointerdown', (e) => {
        drag = { x: e.clientX, y: e.clientY, cx: this.view.cx, cy: this.view.cy };
        c.setPointerCapture(e.pointerId);
      });
      c.addEventListener('pointermove', (e) => {
        if (!drag) return;
        const v = this.view;
        v.cx = drag.cx - (e.clientX - drag.x) / v.scale;
        v.cy = drag.cy + (e.clientY - drag.y) / v.scale;
        v.dirty = true;
        this.draw();
      });
      c.addEventListener('pointerup', () => { drag = null; });
      c.addEventListener('dblclick', () => this.fit());
    }

    // A closed polygon from flat [x0, y0, x1, y1, ...] lot coordinates.
    polygon(ctx, points) {
      ctx.beginPath();
      for (let k = 0; k < points.length; k += 2) {
        const [px, py] = this.toScreen(points[k], points[k + 1]);
        if (k === 0) ctx.moveTo(px, py);
        else ctx.lineTo(px, py);
      }
      ctx.closePath();
    }

    // The robot's footprint corners at a pose, flat.
    footprint(x, y, theta) {
      const r = this.data.robot;
      const front = r.front_overhang_m;
      const back = front - r.length_m;
      const half = r.width_m / 2;
      const c = Math.cos(theta);
      const s = Math.sin(theta);
      const out = [];
      for (const [u, v] of [[front, half], [back, half], [back, -half], [front, -half]]) {
        out.push(x + c * u - s * v, y + s * u + c * v);
      }
      return out;
    }

    line(ctx, xs, ys, n) {
      ctx.beginPath();
      for (let k = 0; k < n; k++) {
        const [px, py] = this.toScreen(xs[k], ys[k]);
        if (k === 0) ctx.moveTo(px, py);
        else ctx.lineTo(px, py);
      }
      ctx.stroke();
    }

    arrow(ctx, pose, color) {
      const len = 0.1;
      const [x, y, th] = pose;
      const [ax, ay] = this.toScreen(x, y);
      const [bx, by] = this.toScreen(x + len * Math.cos(th), y + len * Math.sin(th));
      ctx.strokeStyle = color;
      ctx.fillStyle = color;
      ctx.lineWidth = 2.5;
      ctx.beginPath();
      ctx.moveTo(ax, ay);
      ctx.lineTo(bx, by);
      ctx.stroke();
      const a = Math.atan2(by - ay, bx - ax);
      const head = Math.min(10, 0.35 * Math.hypot(bx - ax, by - ay));
      ctx.beginPath();
      ctx.moveTo(bx, by);
      ctx.lineTo(bx - head * Math.cos(a - 0.45), by - head * Math.sin(a - 0.45));
      ctx.lineTo(bx - head * Math.cos(a + 0.45), by - head * Math.sin(a + 0.45));
      ctx.closePath();
      ctx.fill();
    }

    // What does not change while the episode plays: drawn when the view changes.
    drawBack() {
      const v = this.view;
      const st = this.style;
      const ctx = this.back.getContext('2d');
      ctx.setTransform(v.dpr, 0, 0, v.dpr, 0, 0);
      ctx.fillStyle = st.background;
      ctx.fillRect(0, 0, v.w, v.h);
      const lot = this.data.lot;
      const lotPoly = [lot.x_min, lot.y_min, lot.x_max, lot.y_min, lot.x_max, lot.y_max, lot.x_min, lot.y_max];
      ctx.fillStyle = st.lot;
      this.polygon(ctx, lotPoly);
      ctx.fill();
      // Grid lines at the style's spacing, coarsened by tens until they are 8 px apart.
      let step = st.grid_spacing_m;
      while (step > 0 && step * v.scale < 8) step *= 10;
      if (step > 0) {
        ctx.strokeStyle = st.grid;
        ctx.lineWidth = 1;
        ctx.beginPath();
        for (let x = Math.ceil(lot.x_min / step) * step; x <= lot.x_max + 1e-9; x += step) {
          const [a, b] = [this.toScreen(x, lot.y_min), this.toScreen(x, lot.y_max)];
          ctx.moveTo(a[0], a[1]);
          ctx.lineTo(b[0], b[1]);
        }
        for (let y = Math.ceil(lot.y_min / step) * step; y <= lot.y_max + 1e-9; y += step) {
          const [a, b] = [this.toScreen(lot.x_min, y), this.toScreen(lot.x_max, y)];
          ctx.moveTo(a[0], a[1]);
          ctx.lineTo(b[0], b[1]);
        }
        ctx.stroke();
      }
      ctx.strokeStyle = st.lot_border;
      ctx.lineWidth = 1.5;
      this.polygon(ctx, lotPoly);
      ctx.stroke();
      for (const o of this.data.obstacles) {
        ctx.fillStyle = o.color;
        ctx.globalAlpha = o.blocks_robot ? 1 : 0.45;
        this.polygon(ctx, o.points);
        ctx.fill();
      }
      ctx.globalAlpha = 1;
      // The goal: the footprint there, and the position tolerance around its reference point.
      const g = this.data.goal;
      ctx.strokeStyle = st.goal;
      ctx.lineWidth = 1.5;
      ctx.setLineDash([5, 3]);
      this.polygon(ctx, this.footprint(g.pose[0], g.pose[1], g.pose[2]));
      ctx.stroke();
      ctx.setLineDash([]);
      const [gx, gy] = this.toScreen(g.pose[0], g.pose[1]);
      ctx.beginPath();
      ctx.arc(gx, gy, Math.max(2, g.position_tolerance_m * v.scale), 0, 2 * Math.PI);
      ctx.stroke();
      if (this.path) {
        ctx.strokeStyle = st.planned;
        ctx.lineWidth = 2;
        this.line(ctx, this.path.x, this.path.y, this.path.x.length);
      }
      this.arrow(ctx, this.data.start, st.start);
      this.arrow(ctx, g.pose, st.goal);
      this.trail = this.trailOf();
      v.dirty = false;
    }

    // The rows the driven path is drawn through at this view: each at least 0.75 px from the
    // one before on screen. A 10 x 10 m lot's 240 Hz record has 22,000 rows and as many
    // segments, of which a frame needs a few hundred: the scrubber stays smooth.
    trailOf() {
      const tr = this.track;
      if (!tr || !this.data.record) return new Uint32Array(0);
      const keep = [];
      let lx = Infinity;
      let ly = Infinity;
      for (let k = 0; k < this.rows; k++) {
        const [px, py] = this.toScreen(tr.x[k], tr.y[k]);
        if (Math.abs(px - lx) + Math.abs(py - ly) >= 0.75) {
          keep.push(k);
          lx = px;
          ly = py;
        }
      }
      return Uint32Array.from(keep);
    }

    // The driven path up to row i: the trail's rows before it, then row i itself.
    drawTrail(ctx, i) {
      const tr = this.track;
      const trail = this.trail;
      let lo = 0;
      let hi = trail.length;
      while (lo < hi) {
        const mid = (lo + hi) >> 1;
        if (trail[mid] <= i) lo = mid + 1;
        else hi = mid;
      }
      ctx.beginPath();
      for (let k = 0; k < lo; k++) {
        const [px, py] = this.toScreen(tr.x[trail[k]], tr.y[trail[k]]);
        if (k === 0) ctx.moveTo(px, py);
        else ctx.lineTo(px, py);
      }
      const [px, py] = this.toScreen(tr.x[i], tr.y[i]);
      if (lo === 0) ctx.moveTo(px, py);
      else ctx.lineTo(px, py);
      ctx.stroke();
    }

    // A wheel: a dark bar of half length `len` and half width `hw` centred at (u, w) in the
    // robot's frame, turned by `turn` from its heading.
    drawWheel(ctx, x, y, theta, u, w, len, hw, turn) {
      const c = Math.cos(theta);
      const s = Math.sin(theta);
      const cw = Math.cos(turn);
      const sw = Math.sin(turn);
      const pts = [];
      for (const [a, b] of [[len, hw], [-len, hw], [-len, -hw], [len, -hw]]) {
        const pu = u + cw * a - sw * b;
        const pw = w + sw * a + cw * b;
        pts.push(x + c * pu - s * pw, y + s * pu + c * pw);
      }
      this.polygon(ctx, pts);
      ctx.fill();
    }

    drawRobot(ctx, x, y, theta, steer) {
      const st = this.style;
      const r = this.data.robot;
      ctx.fillStyle = st.robot;
      ctx.strokeStyle = st.wheel;
      ctx.lineWidth = 1;
      this.polygon(ctx, this.footprint(x, y, theta));
      ctx.fill();
      ctx.stroke();
      // Wheels: dark bars at the axle, and a white heading marker towards the front.
      const c = Math.cos(theta);
      const s = Math.sin(theta);
      ctx.fillStyle = st.wheel;
      // A car's wheels are a tenth of its track wide; the study robot's 8 mm.
      const car = r.drive === 'car';
      const hw = car ? 0.05 * r.wheel_base_m : 0.004;
      for (const side of [1, -1]) {
        this.drawWheel(ctx, x, y, theta, 0, side * r.wheel_base_m / 2, r.wheel_radius_m, hw, 0);
      }
      if (car) {
        // The front wheels at their Ackermann angles of the steering (core/model/Ackermann.h).
        const l = r.axle_distance_m;
        const k = l * Math.tan(steer || 0);
        const half = r.wheel_base_m / 2;
        const left = Math.atan2(k, l - half * Math.tan(steer || 0));
        const right = Math.atan2(k, l + half * Math.tan(steer || 0));
        this.drawWheel(ctx, x, y, theta, l, half, r.wheel_radius_m, hw, left);
        this.drawWheel(ctx, x, y, theta, l, -half, r.wheel_radius_m, hw, right);
      }
      const tip = r.front_overhang_m * 0.8;
      const baseU = -0.25 * r.length_m;
      const half = 0.2 * r.width_m;
      ctx.fillStyle = st.robot_marker;
      this.polygon(ctx, [x + c * tip, y + s * tip,
        x + c * baseU - s * half, y + s * baseU + c * half,
        x + c * baseU + s * half, y + s * baseU - c * half]);
      ctx.fill();
      // Too small to see at this zoom: a ring around it.
      if (r.length_m * this.view.scale < 10) {
        const [px, py] = this.toScreen(x, y);
        ctx.strokeStyle = st.robot;
        ctx.lineWidth = 2;
        ctx.beginPath();
        ctx.arc(px, py, 9, 0, 2 * Math.PI);
        ctx.stroke();
      }
    }

    // The scale bar at this zoom: the longest 1, 2 or 5 x 10^k mm no wider than 120 CSS px,
    // {mm, px, label} (lengths in mm, as on every page).
    scaleBar() {
      const pxPerMm = this.view.scale / 1000;
      const most = 120 / pxPerMm;
      let mm = Math.pow(10, Math.floor(Math.log10(most)));
      if (5 * mm <= most) mm *= 5;
      else if (2 * mm <= most) mm *= 2;
      return { mm, px: mm * pxPerMm, label: mm + ' mm' };
    }

    // The scale bar, bottom left, in screen space (it stays while the lot pans).
    drawScaleBar(ctx) {
      const bar = this.scaleBar();
      const x = 12;
      const y = this.view.h - 14;
      ctx.save();
      ctx.fillStyle = 'rgba(255,255,255,0.8)';
      ctx.fillRect(x - 6, y - 20, bar.px + 12, 28);
      ctx.strokeStyle = '#24292f';
      ctx.lineWidth = 2;
      ctx.beginPath();
      ctx.moveTo(x, y - 5);
      ctx.lineTo(x, y);
      ctx.lineTo(x + bar.px, y);
      ctx.lineTo(x + bar.px, y - 5);
      ctx.stroke();
      ctx.fillStyle = '#24292f';
      ctx.font = '12px sans-serif';
      ctx.fillText(bar.label, x, y - 8);
      ctx.restore();
    }

    draw() {
      if (!this.view) return;
      if (this.view.dirty) this.drawBack();
      const v = this.view;
      const ctx = this.canvas.getContext('2d');
      ctx.setTransform(1, 0, 0, 1, 0, 0);
      ctx.drawImage(this.back, 0, 0);
      ctx.setTransform(v.dpr, 0, 0, v.dpr, 0, 0);
      if (this.track) this.drawTrack(ctx);
      this.drawScaleBar(ctx);  // last: nothing covers it
    }

    // What moves as the episode plays: the contacts so far, the path driven, the reference
    // pose, the robot, the estimate.
    drawTrack(ctx) {
      const st = this.style;
      const i = this.index;
      const tr = this.track;
      const t = tr.t[i];
      // Obstacles touched so far, in the contact colour.
      ctx.strokeStyle = st.contact;
      ctx.lineWidth = 3;
      for (const c of this.contacts) {
        if (c.t_s > t) continue;
        const o = this.data.obstacles[c.obstacle];
        if (o) {
          this.polygon(ctx, o.points);
          ctx.stroke();
        }
      }
      if (this.data.record) {
        ctx.strokeStyle = st.executed;
        ctx.lineWidth = 2;
        this.drawTrail(ctx, i);
      }
      if (tr.xr) {
        ctx.strokeStyle = st.reference;
        ctx.lineWidth = 1.2;
        this.polygon(ctx, this.footprint(tr.xr[i], tr.yr[i], tr.thr[i]));
        ctx.stroke();
      }
      this.drawRobot(ctx, tr.x[i], tr.y[i], tr.theta[i], tr.steer ? tr.steer[i] : 0);
      if (tr.xe) {
        ctx.strokeStyle = '#0b7285';
        ctx.lineWidth = 1.2;
        ctx.setLineDash([3, 2]);
        this.polygon(ctx, this.footprint(tr.xe[i], tr.ye[i], tr.the[i]));
        ctx.stroke();
        ctx.setLineDash([]);
      }
      // Where each contact so far began: a ring at the robot's reference point then.
      ctx.strokeStyle = st.contact;
      ctx.lineWidth = 2;
      for (const c of this.contacts) {
        if (c.t_s > t) continue;
        const [px, py] = this.toScreen(tr.x[c.index], tr.y[c.index]);
        ctx.beginPath();
        ctx.arc(px, py, 7, 0, 2 * Math.PI);
        ctx.stroke();
      }
    }
  }

  // What the replay's colours mean, as a list to put beside it: each item a swatch in the
  // colour the replay draws with (a dashed one for a dashed line) and its meaning.
  P.replayLegend = function (replay) {
    const st = replay.style;
    const items = [
      ['planned', st.planned, 'plan', false],
      ['executed', st.executed, 'path driven', false],
      ['robot', st.robot, 'robot', false],
      ['reference', st.reference, 'reference pose (outline)', false],
      ['start', st.start, 'start', false],
      ['goal', st.goal, 'goal and its tolerance', false],
      ['contact', st.contact, 'contact: obstacle touched, where it began', false],
    ];
    if (replay.track && replay.track.xe) items.splice(4, 0, ['estimate', '#0b7285', 'estimate (dashed outline)', true]);
    return P.el('ul', { class: 'legend', id: 'replay-legend' }, items.map(([key, color, text, dashed]) => {
      const swatch = P.el('span', { class: 'swatch' + (dashed ? ' dashed' : '') });
      swatch.style.borderColor = color;
      return P.el('li', { 'data-key': key, 'data-color': color }, swatch, text);
    }));
  };

  P.Replay = Replay;
})(parksim);
