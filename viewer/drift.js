// newtop view: the drift of the integrals, |I(t) - I(0)| / |I(0)| (absolute where I(0) = 0), on a
// log scale against t, drawn on a 2D canvas with a cursor at the current time. Each pixel column
// shows the largest drift of the rows that fall in it, so no spike is hidden.
(function () {
  "use strict";
  const EPS = 2.220446049250313e-16;
  const PALETTE = ["#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b"];
  let canvas, ctx, base, frame, tmin, tmax;

  function drifts(values) {
    const i0 = values[0], rel = i0 !== 0;
    return { rel: rel, d: values.map((v) => Math.max(Math.abs(v - i0) / (rel ? Math.abs(i0) : 1), EPS / 2)) };
  }
  function init(c, t, integrals) {
    canvas = c;
    ctx = canvas.getContext("2d");
    tmin = t[0];
    tmax = t[t.length - 1] > t[0] ? t[t.length - 1] : t[0] + 1;
    const names = Object.keys(integrals);
    const series = names.map((n) => drifts(integrals[n]));
    let lo = EPS / 2, hi = EPS;
    series.forEach((s) => s.d.forEach((v) => { hi = Math.max(hi, v); }));
    const dmin = Math.floor(Math.log10(lo)), dmax = Math.max(Math.ceil(Math.log10(hi)), dmin + 1);
    const W = canvas.width, H = canvas.height;
    frame = { x0: 90, x1: W - 16, y0: 16, y1: H - 70 };
    const X = (tt) => frame.x0 + (tt - tmin) / (tmax - tmin) * (frame.x1 - frame.x0);
    const Y = (v) => frame.y1 - (Math.log10(v) - dmin) / (dmax - dmin) * (frame.y1 - frame.y0);
    ctx.fillStyle = "#fff";
    ctx.fillRect(0, 0, W, H);
    ctx.font = "20px sans-serif";
    ctx.strokeStyle = "#ccc";
    ctx.fillStyle = "#333";
    ctx.lineWidth = 1;
    const step = Math.max(1, Math.ceil((dmax - dmin) / 8));
    for (let e = dmin; e <= dmax; e += step) {
      const y = Y(Math.pow(10, e));
      ctx.beginPath(); ctx.moveTo(frame.x0, y); ctx.lineTo(frame.x1, y); ctx.stroke();
      ctx.textAlign = "right"; ctx.fillText("1e" + e, frame.x0 - 6, y + 6);
    }
    for (let k = 0; k <= 4; ++k) {
      const tt = tmin + k / 4 * (tmax - tmin), x = X(tt);
      ctx.textAlign = "center"; ctx.fillText(Number(tt.toPrecision(4)).toString(), x, frame.y1 + 24);
    }
    ctx.fillText("t", (frame.x0 + frame.x1) / 2, frame.y1 + 48);
    ctx.strokeStyle = "#999"; ctx.setLineDash([4, 4]);
    ctx.beginPath(); ctx.moveTo(frame.x0, Y(EPS)); ctx.lineTo(frame.x1, Y(EPS)); ctx.stroke();
    ctx.setLineDash([]);
    let legendX = frame.x0 - 60;
    series.forEach((s, j) => {
      ctx.strokeStyle = PALETTE[j % PALETTE.length];
      ctx.lineWidth = 2;
      ctx.beginPath();
      let col = -1, colMax = 0, first = true;
      const flush = () => {
        if (col < 0) return;
        const y = Y(colMax);
        if (first) { ctx.moveTo(col, y); first = false; } else ctx.lineTo(col, y);
      };
      s.d.forEach((v, i) => {
        const x = Math.round(X(t[i]));
        if (x !== col) { flush(); col = x; colMax = v; } else colMax = Math.max(colMax, v);
      });
      flush();
      ctx.stroke();
      const ly = frame.y1 + 60, lx = legendX;
      ctx.fillStyle = ctx.strokeStyle; ctx.fillRect(lx, ly - 12, 16, 4);
      ctx.fillStyle = "#333"; ctx.textAlign = "left";
      const text = names[j] + (s.rel ? "" : " (abs)");
      ctx.fillText(text, lx + 20, ly - 4);
      legendX += 20 + ctx.measureText(text).width + 18;
    });
    ctx.fillStyle = "#999"; ctx.textAlign = "left"; ctx.fillText("ε", frame.x1 - 20, Y(EPS) - 6);
    base = ctx.getImageData(0, 0, W, H);
  }
  function cursor(t) {
    if (!ctx) return;
    ctx.putImageData(base, 0, 0);
    const x = frame.x0 + (t - tmin) / (tmax - tmin) * (frame.x1 - frame.x0);
    ctx.strokeStyle = "#000"; ctx.lineWidth = 1.5;
    ctx.beginPath(); ctx.moveTo(x, frame.y0); ctx.lineTo(x, frame.y1); ctx.stroke();
  }
  window.NewtopDrift = { init: init, cursor: cursor };
})();
