// OpenRAPID run report: draws the views of the page from the run's data (the JSON in
// #run-data) with the plain canvas 2D API. No library, no network.
// When every view has drawn, the body's dataset gets drawn = "yes"; every error
// (uncaught, or console.error) counts in its dataset's errors, so a headless browser
// can check the page from its DOM.
(function () {
  "use strict";

  var body = document.body;
  var errorCount = 0;
  function noteError() {
    errorCount += 1;
    body.dataset.errors = String(errorCount);
  }
  window.addEventListener("error", noteError);
  var consoleError = console.error;
  console.error = function () {
    noteError();
    return consoleError.apply(console, arguments);
  };

  var INK = "#1d2430";
  var MUTED = "#5d6878";
  var GRID = "#e3e7ee";
  var BAD = "#c62828";
  var AXIS_COLOURS = ["#1f77b4", "#ff7f0e", "#2ca02c", "#9467bd", "#8c564b", "#d62728"];
  var FONT = "13px 'Segoe UI', 'Helvetica Neue', Arial, sans-serif";
  // The plots' margins left and right of the time axis, CSS pixels.
  var PLOT_LEFT = 58;
  var PLOT_RIGHT = 12;
  var SMALL = "12px 'Segoe UI', 'Helvetica Neue', Arial, sans-serif";

  var data;
  try {
    data = JSON.parse(document.getElementById("run-data").textContent);
  } catch (e) {
    console.error("the report's data cannot be read: " + e);
    return;
  }
  var path = data.path;
  var selected = -1;
  // The time the pointer is at in a plot (s), shown in every plot and on the path.
  var hoverT = null;

  // The index of the path point nearest time `t` (the times grow).
  function nearestIndex(t) {
    var lo = 0;
    var hi = path.t.length - 1;
    if (hi < 0) {
      return -1;
    }
    while (hi - lo > 1) {
      var mid = (lo + hi) >> 1;
      if (path.t[mid] <= t) {
        lo = mid;
      } else {
        hi = mid;
      }
    }
    return Math.abs(path.t[hi] - t) < Math.abs(path.t[lo] - t) ? hi : lo;
  }

  // ---- helpers -------------------------------------------------------------

  // A canvas sized for the screen's pixel density; returns its 2D context in CSS pixels.
  function prepare(canvas, width, height) {
    var ratio = window.devicePixelRatio || 1;
    canvas.width = Math.round(width * ratio);
    canvas.height = Math.round(height * ratio);
    canvas.style.height = height + "px";
    var ctx = canvas.getContext("2d");
    ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
    ctx.clearRect(0, 0, width, height);
    return ctx;
  }

  // Round tick values covering lo..hi, about `count` of them.
  function ticks(lo, hi, count) {
    if (!(hi > lo)) {
      hi = lo + 1;
    }
    var raw = (hi - lo) / count;
    var step = Math.pow(10, Math.floor(Math.log(raw) / Math.LN10));
    var ratio = raw / step;
    if (ratio >= 7.5) {
      step *= 10;
    } else if (ratio >= 3.5) {
      step *= 5;
    } else if (ratio >= 1.5) {
      step *= 2;
    }
    var out = [];
    for (var v = Math.ceil(lo / step) * step; v <= hi + step * 1e-9; v += step) {
      out.push(Math.abs(v) < step * 1e-9 ? 0 : v);
    }
    return { values: out, step: step };
  }

  function label(value, step) {
    var decimals = Math.max(0, Math.min(4, -Math.floor(Math.log(step) / Math.LN10 + 1e-9)));
    return value.toFixed(decimals);
  }

  // The speed colour scale: blue (slow) through green to red (fast).
  var STOPS = [[45, 50, 160], [30, 136, 229], [0, 172, 150], [124, 179, 66], [251, 140, 0], [211, 47, 47]];
  function speedColour(f) {
    f = Math.max(0, Math.min(1, isFinite(f) ? f : 0)) * (STOPS.length - 1);
    var i = Math.min(STOPS.length - 2, Math.floor(f));
    var u = f - i;
    var a = STOPS[i];
    var b = STOPS[i + 1];
    return "rgb(" + Math.round(a[0] + (b[0] - a[0]) * u) + "," + Math.round(a[1] + (b[1] - a[1]) * u) + "," +
      Math.round(a[2] + (b[2] - a[2]) * u) + ")";
  }

  function maxOf(values) {
    var m = 0;
    for (var i = 0; i < values.length; i++) {
      if (values[i] > m) {
        m = values[i];
      }
    }
    return m;
  }
  var topSpeed = Math.max(1, maxOf(path.v));

  // ---- 3D view of the TCP path ---------------------------------------------

  var view3d = {
    canvas: document.getElementById("path3d"),
    azimuth: 0,
    elevation: 0,
    zoom: 1,
    centre: [0, 0, 0],
    radius: 1,
  };

  function resetView(azimuthDeg, elevationDeg) {
    view3d.azimuth = azimuthDeg * Math.PI / 180;
    view3d.elevation = elevationDeg * Math.PI / 180;
    view3d.zoom = 1;
  }

  // The box around the path, the programmed points and the base.
  function sceneBounds() {
    var lo = [data.base[0], data.base[1], data.base[2]];
    var hi = lo.slice();
    function take(x, y, z) {
      var p = [x, y, z];
      for (var k = 0; k < 3; k++) {
        lo[k] = Math.min(lo[k], p[k]);
        hi[k] = Math.max(hi[k], p[k]);
      }
    }
    for (var i = 0; i < path.t.length; i++) {
      take(path.x[i], path.y[i], path.z[i]);
    }
    data.moves.forEach(function (m) {
      take(m.p[0], m.p[1], m.p[2]);
    });
    view3d.centre = [(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2];
    var r = 0;
    for (var k = 0; k < 3; k++) {
      r = Math.max(r, (hi[k] - lo[k]) / 2);
    }
    view3d.radius = Math.max(r, 50);
    view3d.lo = lo;
    view3d.hi = hi;
  }

  // Orthographic camera: a point in mm to screen pixels and its depth (larger: nearer).
  function projector(width, height) {
    var a = view3d.azimuth;
    var e = view3d.elevation;
    var right = [-Math.sin(a), Math.cos(a), 0];
    var up = [-Math.sin(e) * Math.cos(a), -Math.sin(e) * Math.sin(a), Math.cos(e)];
    var toward = [Math.cos(e) * Math.cos(a), Math.cos(e) * Math.sin(a), Math.sin(e)];
    var scale = view3d.zoom * 0.42 * Math.min(width, height) / view3d.radius;
    var c = view3d.centre;
    var project = function (x, y, z) {
      var d = [x - c[0], y - c[1], z - c[2]];
      return {
        x: width / 2 + scale * (d[0] * right[0] + d[1] * right[1]),
        y: height / 2 - scale * (d[0] * up[0] + d[1] * up[1] + d[2] * up[2]),
        depth: d[0] * toward[0] + d[1] * toward[1] + d[2] * toward[2],
      };
    };
    project.scale = scale;
    return project;
  }

  function drawFloor(ctx, project) {
    var span = Math.max(view3d.hi[0] - view3d.lo[0], view3d.hi[1] - view3d.lo[1], 200);
    var step = ticks(0, span, 8).step;
    var z = data.base[2];
    var x0 = Math.floor((view3d.lo[0] - step) / step) * step;
    var x1 = Math.ceil((view3d.hi[0] + step) / step) * step;
    var y0 = Math.floor((view3d.lo[1] - step) / step) * step;
    var y1 = Math.ceil((view3d.hi[1] + step) / step) * step;
    ctx.strokeStyle = GRID;
    ctx.lineWidth = 1;
    ctx.beginPath();
    for (var x = x0; x <= x1 + 1e-6; x += step) {
      var a = project(x, y0, z);
      var b = project(x, y1, z);
      ctx.moveTo(a.x, a.y);
      ctx.lineTo(b.x, b.y);
    }
    for (var y = y0; y <= y1 + 1e-6; y += step) {
      var c = project(x0, y, z);
      var d = project(x1, y, z);
      ctx.moveTo(c.x, c.y);
      ctx.lineTo(d.x, d.y);
    }
    ctx.stroke();
    return step;
  }

  function drawBase(ctx, project) {
    var b = data.base;
    var r = Math.max(60, view3d.radius * 0.08);
    ctx.fillStyle = "rgba(141,153,174,0.55)";
    ctx.strokeStyle = "#6c7a91";
    ctx.lineWidth = 1.2;
    ctx.beginPath();
    for (var i = 0; i <= 32; i++) {
      var a = i / 32 * 2 * Math.PI;
      var p = project(b[0] + r * Math.cos(a), b[1] + r * Math.sin(a), b[2]);
      if (i === 0) {
        ctx.moveTo(p.x, p.y);
      } else {
        ctx.lineTo(p.x, p.y);
      }
    }
    ctx.fill();
    ctx.stroke();
    // The world axes at the base, labelled.
    var length = Math.max(100, view3d.radius * 0.3);
    var o = project(b[0], b[1], b[2]);
    var axes = [["X", [length, 0, 0], "#d62728"], ["Y", [0, length, 0], "#2ca02c"], ["Z", [0, 0, length], "#1f6feb"]];
    ctx.font = "bold " + FONT;
    axes.forEach(function (axis) {
      var v = axis[1];
      var tip = project(b[0] + v[0], b[1] + v[1], b[2] + v[2]);
      ctx.strokeStyle = axis[2];
      ctx.fillStyle = axis[2];
      ctx.lineWidth = 2.5;
      ctx.beginPath();
      ctx.moveTo(o.x, o.y);
      ctx.lineTo(tip.x, tip.y);
      ctx.stroke();
      ctx.fillText(axis[0], tip.x + 5, tip.y - 5);
    });
    // The label to the left, where the default view's X axis is not.
    ctx.fillStyle = MUTED;
    ctx.font = SMALL;
    ctx.textAlign = "right";
    ctx.fillText("robot base", o.x - 12, o.y + 18);
    ctx.textAlign = "left";
  }

  function drawPath(ctx, project) {
    var n = path.t.length;
    var previous = null;
    ctx.lineCap = "round";
    for (var i = 0; i < n; i++) {
      var p = project(path.x[i], path.y[i], path.z[i]);
      if (previous) {
        var on = selected < 0 || path.m[i] === selected;
        ctx.strokeStyle = speedColour(path.v[i] / topSpeed);
        ctx.globalAlpha = on ? 1 : 0.18;
        ctx.lineWidth = selected >= 0 && on ? 4.5 : 2.5;
        ctx.beginPath();
        ctx.moveTo(previous.x, previous.y);
        ctx.lineTo(p.x, p.y);
        ctx.stroke();
      }
      previous = p;
    }
    ctx.globalAlpha = 1;
  }

  function drawPoints(ctx, project) {
    var labels = {};
    data.moves.forEach(function (m, i) {
      var p = project(m.p[0], m.p[1], m.p[2]);
      var dim = selected >= 0 && selected !== i;
      ctx.globalAlpha = dim ? 0.35 : 1;
      if (m.zone > 0) {
        ctx.strokeStyle = "#7a869a";
        ctx.lineWidth = 1.2;
        ctx.setLineDash([4, 3]);
        ctx.beginPath();
        ctx.arc(p.x, p.y, m.zone * project.scale, 0, 2 * Math.PI);
        ctx.stroke();
        ctx.setLineDash([]);
      }
      ctx.fillStyle = INK;
      if (m.fine) {
        ctx.fillRect(p.x - 4, p.y - 4, 8, 8);
      } else {
        ctx.beginPath();
        ctx.arc(p.x, p.y, 4, 0, 2 * Math.PI);
        ctx.fill();
      }
      if (m.cpf) {
        ctx.strokeStyle = BAD;
        ctx.lineWidth = 2.5;
        ctx.beginPath();
        ctx.arc(p.x, p.y, 8, 0, 2 * Math.PI);
        ctx.stroke();
      }
      // Moves to the same place share one label.
      var key = Math.round(p.x) + "," + Math.round(p.y);
      if (!labels[key]) {
        labels[key] = { x: p.x, y: p.y, names: [] };
      }
      labels[key].names.push(String(i + 1));
    });
    ctx.globalAlpha = 1;
    if (data.moves.length > 80) {
      return;
    }
    ctx.font = SMALL;
    ctx.fillStyle = INK;
    Object.keys(labels).forEach(function (key) {
      var l = labels[key];
      var text = l.names.length > 4 ? l.names.slice(0, 4).join(",") + "…" : l.names.join(",");
      ctx.fillText(text, l.x + 7, l.y - 7);
    });
  }

  // Where the robot was at the time the pointer is at in a plot.
  function drawHoverPoint(ctx, project) {
    var i = hoverT === null ? -1 : nearestIndex(hoverT);
    if (i < 0) {
      return;
    }
    var p = project(path.x[i], path.y[i], path.z[i]);
    ctx.fillStyle = "#ffffff";
    ctx.strokeStyle = INK;
    ctx.lineWidth = 2.5;
    ctx.beginPath();
    ctx.arc(p.x, p.y, 7, 0, 2 * Math.PI);
    ctx.fill();
    ctx.stroke();
    ctx.font = FONT;
    ctx.fillStyle = INK;
    ctx.fillText("t = " + path.t[i].toFixed(3) + " s · " + path.v[i].toFixed(0) + " mm/s", p.x + 12, p.y + 18);
  }

  function draw3d() {
    var canvas = view3d.canvas;
    var width = canvas.clientWidth || 960;
    var height = 600;
    var ctx = prepare(canvas, width, height);
    ctx.fillStyle = "#fbfcfd";
    ctx.fillRect(0, 0, width, height);
    var project = projector(width, height);
    var grid = drawFloor(ctx, project);
    drawBase(ctx, project);
    drawPath(ctx, project);
    drawPoints(ctx, project);
    drawHoverPoint(ctx, project);
    ctx.fillStyle = MUTED;
    ctx.font = SMALL;
    ctx.fillText("floor grid: " + grid + " mm · world frame, mm", 10, height - 10);
    if (selected >= 0) {
      ctx.fillStyle = INK;
      ctx.font = FONT;
      ctx.fillText("move " + (selected + 1) + " highlighted (click it again to show all)", 10, 20);
    }
    if (path.t.length === 0) {
      ctx.fillStyle = MUTED;
      ctx.font = FONT;
      ctx.fillText("The robot did not move.", width / 2 - 70, height / 2);
    }
  }

  function drawLegend() {
    var canvas = document.getElementById("speed-legend");
    var ctx = prepare(canvas, 150, 330);
    var top = 30;
    var bottom = 310;
    ctx.font = FONT;
    ctx.fillStyle = INK;
    ctx.fillText("TCP speed [mm/s]", 0, 16);
    for (var y = top; y < bottom; y++) {
      ctx.fillStyle = speedColour((bottom - y) / (bottom - top));
      ctx.fillRect(10, y, 24, 1);
    }
    ctx.strokeStyle = MUTED;
    ctx.strokeRect(10.5, top + 0.5, 24, bottom - top);
    var t = ticks(0, topSpeed, 6);
    ctx.font = SMALL;
    ctx.fillStyle = INK;
    t.values.forEach(function (v) {
      var y = bottom - (v / topSpeed) * (bottom - top);
      ctx.fillRect(34, y, 5, 1);
      ctx.fillText(label(v, t.step), 44, y + 4);
    });
  }

  function hook3d() {
    var canvas = view3d.canvas;
    var drag = null;
    canvas.addEventListener("pointerdown", function (e) {
      drag = { x: e.clientX, y: e.clientY, azimuth: view3d.azimuth, elevation: view3d.elevation };
      canvas.setPointerCapture(e.pointerId);
    });
    canvas.addEventListener("pointermove", function (e) {
      if (!drag) {
        return;
      }
      view3d.azimuth = drag.azimuth - (e.clientX - drag.x) * 0.01;
      var limit = Math.PI / 2 - 0.01;
      view3d.elevation = Math.max(-limit, Math.min(limit, drag.elevation + (e.clientY - drag.y) * 0.01));
      draw3d();
    });
    var end = function () {
      drag = null;
    };
    canvas.addEventListener("pointerup", end);
    canvas.addEventListener("pointercancel", end);
    canvas.addEventListener("wheel", function (e) {
      e.preventDefault();
      view3d.zoom = Math.max(0.1, Math.min(50, view3d.zoom * Math.exp(-e.deltaY * 0.0015)));
      draw3d();
    }, { passive: false });
    var button = function (id, azimuth, elevation) {
      document.getElementById(id).addEventListener("click", function () {
        resetView(azimuth, elevation);
        draw3d();
      });
    };
    button("reset-view", -50, 25);
    button("top-view", -90, 89.4);
    button("front-view", 0, 0);
  }

  // ---- plots against time --------------------------------------------------

  // A plot in `parent`: series of (t, y), horizontal reference lines, axes with units.
  function plot(parent, spec) {
    var canvas = document.createElement("canvas");
    canvas.className = "plot";
    canvas.setAttribute("aria-label", spec.title);
    parent.appendChild(canvas);
    var draw = function () {
      var width = canvas.clientWidth || 400;
      var height = spec.height || 190;
      var ctx = prepare(canvas, width, height);
      var left = PLOT_LEFT;
      var right = PLOT_RIGHT;
      var top = 24;
      var bottom = 38;
      var tEnd = Math.max(data.cycle, path.t.length ? path.t[path.t.length - 1] : 0, 1e-3);
      var lo = Infinity;
      var hi = -Infinity;
      spec.series.forEach(function (s) {
        s.y.forEach(function (v) {
          lo = Math.min(lo, v);
          hi = Math.max(hi, v);
        });
      });
      spec.lines.forEach(function (l) {
        lo = Math.min(lo, l.y);
        hi = Math.max(hi, l.y);
      });
      if (!isFinite(lo)) {
        lo = 0;
        hi = 1;
      }
      var pad = (hi - lo) * 0.05 || 1;
      lo -= pad;
      hi += pad;
      var px = function (t) {
        return left + (t / tEnd) * (width - left - right);
      };
      var py = function (v) {
        return top + (hi - v) / (hi - lo) * (height - top - bottom);
      };
      // The selected move's time span.
      if (selected >= 0 && data.moves[selected]) {
        var m = data.moves[selected];
        ctx.fillStyle = "rgba(31,111,235,0.12)";
        ctx.fillRect(px(m.start), top, Math.max(1, px(m.end) - px(m.start)), height - top - bottom);
      }
      ctx.font = SMALL;
      ctx.strokeStyle = GRID;
      ctx.fillStyle = MUTED;
      ctx.lineWidth = 1;
      var yt = ticks(lo, hi, 5);
      yt.values.forEach(function (v) {
        var y = Math.round(py(v)) + 0.5;
        ctx.beginPath();
        ctx.moveTo(left, y);
        ctx.lineTo(width - right, y);
        ctx.stroke();
        ctx.textAlign = "right";
        ctx.fillText(label(v, yt.step), left - 6, y + 4);
      });
      var xt = ticks(0, tEnd, Math.max(3, Math.floor((width - left) / 70)));
      xt.values.forEach(function (t) {
        var x = Math.round(px(t)) + 0.5;
        ctx.beginPath();
        ctx.moveTo(x, top);
        ctx.lineTo(x, height - bottom);
        ctx.stroke();
        ctx.textAlign = "center";
        ctx.fillText(label(t, xt.step), x, height - bottom + 15);
      });
      ctx.textAlign = "left";
      ctx.fillText("time [s]", width - right - 50, height - 4);
      ctx.save();
      ctx.translate(12, top + (height - top - bottom) / 2);
      ctx.rotate(-Math.PI / 2);
      ctx.textAlign = "center";
      ctx.fillText(spec.unit, 0, 0);
      ctx.restore();
      ctx.strokeStyle = "#9aa5b5";
      ctx.strokeRect(left + 0.5, top + 0.5, width - left - right, height - top - bottom);
      ctx.save();
      ctx.beginPath();
      ctx.rect(left, top, width - left - right, height - top - bottom);
      ctx.clip();
      spec.lines.forEach(function (l) {
        ctx.strokeStyle = BAD;
        ctx.setLineDash([6, 4]);
        ctx.lineWidth = 1.3;
        ctx.beginPath();
        ctx.moveTo(left, py(l.y));
        ctx.lineTo(width - right, py(l.y));
        ctx.stroke();
        ctx.setLineDash([]);
      });
      spec.series.forEach(function (s) {
        ctx.strokeStyle = s.colour;
        ctx.lineWidth = 1.8;
        ctx.beginPath();
        for (var i = 0; i < s.y.length; i++) {
          var x = px(path.t[i]);
          var y = py(s.y[i]);
          if (i === 0) {
            ctx.moveTo(x, y);
          } else {
            ctx.lineTo(x, y);
          }
        }
        ctx.stroke();
      });
      ctx.restore();
      var at = hoverT === null ? -1 : nearestIndex(hoverT);
      if (at >= 0) {
        var hx = Math.round(px(path.t[at])) + 0.5;
        ctx.strokeStyle = INK;
        ctx.lineWidth = 1;
        ctx.beginPath();
        ctx.moveTo(hx, top);
        ctx.lineTo(hx, height - bottom);
        ctx.stroke();
        ctx.font = SMALL;
        var readout = spec.series.map(function (s) {
          return s.y[at].toFixed(1);
        }).join(", ");
        var text = readout + " " + spec.unit + " at " + path.t[at].toFixed(3) + " s";
        var textWidth = ctx.measureText(text).width;
        var tx = hx > width / 2 ? hx - 6 - textWidth : hx + 6;
        ctx.textAlign = "left";
        ctx.fillStyle = "rgba(255,255,255,0.9)";
        ctx.fillRect(tx - 3, top + 3, textWidth + 6, 16);
        ctx.fillStyle = INK;
        ctx.fillText(text, tx, top + 15);
      }
      ctx.fillStyle = INK;
      ctx.font = "600 " + FONT;
      ctx.fillText(spec.title, left, 16);
      ctx.font = SMALL;
      ctx.fillStyle = BAD;
      ctx.textAlign = "right";
      if (spec.lines.length) {
        ctx.fillText(spec.limitText, width - right, 16);
      }
      ctx.textAlign = "left";
    };
    draw();
    // The pointer's time, shown in every plot and on the path.
    canvas.addEventListener("pointermove", function (e) {
      var box = canvas.getBoundingClientRect();
      var tEnd = Math.max(data.cycle, path.t.length ? path.t[path.t.length - 1] : 0, 1e-3);
      var f = (e.clientX - box.left - PLOT_LEFT) / Math.max(1, box.width - PLOT_LEFT - PLOT_RIGHT);
      hoverT = f >= 0 && f <= 1 ? f * tEnd : null;
      scheduleRedraw();
    });
    canvas.addEventListener("pointerleave", function () {
      hoverT = null;
      scheduleRedraw();
    });
    return draw;
  }

  // Redraws every view once per frame at most.
  var pending = false;
  function scheduleRedraw() {
    if (pending) {
      return;
    }
    pending = true;
    window.requestAnimationFrame(function () {
      pending = false;
      draw3d();
      redrawPlots.forEach(function (redraw) {
        redraw();
      });
    });
  }

  var redrawPlots = [];

  function drawPlots() {
    var pos = document.getElementById("joint-pos");
    var speed = document.getElementById("joint-speed");
    for (var a = 0; a < 6; a++) {
      var lim = data.limits[a];
      redrawPlots.push(plot(pos, {
        title: "Axis " + (a + 1),
        unit: "deg",
        series: [{ y: path.j[a], colour: AXIS_COLOURS[a] }],
        lines: [{ y: lim[0] }, { y: lim[1] }],
        limitText: "limits " + lim[0] + " … " + lim[1] + " deg",
      }));
      var top = data.max_speeds[a];
      redrawPlots.push(plot(speed, {
        title: "Axis " + (a + 1),
        unit: "deg/s",
        series: [{ y: path.jv[a], colour: AXIS_COLOURS[a] }],
        lines: [{ y: -top }, { y: top }],
        limitText: "max ±" + top + " deg/s",
      }));
    }
    // External axes (a track, a turntable), after the robot's six.
    (data.ext || []).forEach(function (e, i) {
      var colour = AXIS_COLOURS[i % AXIS_COLOURS.length];
      redrawPlots.push(plot(pos, {
        title: e.name,
        unit: e.unit,
        series: [{ y: e.y, colour: colour }],
        lines: [{ y: e.limits[0] }, { y: e.limits[1] }],
        limitText: "limits " + e.limits[0] + " … " + e.limits[1] + " " + e.unit,
      }));
      redrawPlots.push(plot(speed, {
        title: e.name,
        unit: e.unit + "/s",
        series: [{ y: e.v, colour: colour }],
        lines: [{ y: -e.max_speed }, { y: e.max_speed }],
        limitText: "max ±" + e.max_speed + " " + e.unit + "/s",
      }));
    });
    redrawPlots.push(plot(document.getElementById("tcp-speed"), {
      title: "TCP speed",
      unit: "mm/s",
      height: 200,
      series: [{ y: path.v, colour: "#1f6feb" }],
      lines: [],
      limitText: "",
    }));
  }

  // ---- I/O timeline ----------------------------------------------------------

  function drawIo() {
    var parent = document.getElementById("io");
    if (!data.signals.length) {
      parent.innerHTML = "<p class=\"empty\">No signal changed during the run.</p>";
      return function () {};
    }
    var canvas = document.createElement("canvas");
    canvas.className = "plot";
    parent.appendChild(canvas);
    if (data.changes_cut > 0) {
      var note = document.createElement("p");
      note.className = "empty";
      note.textContent = data.changes_cut + " later signal changes are not drawn.";
      parent.appendChild(note);
    }
    var draw = function () {
      var row = 34;
      var left = 170;
      var right = 12;
      var top = 8;
      var bottom = 36;
      var width = canvas.clientWidth || 900;
      var height = top + bottom + row * data.signals.length;
      var ctx = prepare(canvas, width, height);
      var tEnd = Math.max(data.cycle, 1e-3);
      var px = function (t) {
        return left + Math.max(0, Math.min(1, t / tEnd)) * (width - left - right);
      };
      ctx.font = SMALL;
      var xt = ticks(0, tEnd, Math.max(3, Math.floor((width - left) / 80)));
      ctx.strokeStyle = GRID;
      ctx.fillStyle = MUTED;
      xt.values.forEach(function (t) {
        var x = Math.round(px(t)) + 0.5;
        ctx.beginPath();
        ctx.moveTo(x, top);
        ctx.lineTo(x, height - bottom);
        ctx.stroke();
        ctx.textAlign = "center";
        ctx.fillText(label(t, xt.step), x, height - bottom + 15);
      });
      ctx.textAlign = "left";
      ctx.fillText("time [s]", width - right - 50, height - 4);
      data.signals.forEach(function (s, k) {
        var y0 = top + k * row;
        var values = [s.first].concat(s.steps.map(function (st) {
          return st[1];
        }));
        var lo = Math.min.apply(null, values.concat([0]));
        var hi = Math.max.apply(null, values.concat([1]));
        var py = function (v) {
          return y0 + row - 7 - (v - lo) / (hi - lo || 1) * (row - 14);
        };
        ctx.fillStyle = INK;
        ctx.font = FONT;
        ctx.fillText(s.name, 8, y0 + row / 2 + 4);
        ctx.strokeStyle = "#edf0f4";
        ctx.beginPath();
        ctx.moveTo(left, y0 + row + 0.5);
        ctx.lineTo(width - right, y0 + row + 0.5);
        ctx.stroke();
        // High stretches shaded, the step line on top.
        var points = [[0, s.first]].concat(s.steps).concat([[tEnd, values[values.length - 1]]]);
        ctx.fillStyle = "rgba(31,111,235,0.13)";
        for (var i = 0; i + 1 < points.length; i++) {
          if (points[i][1] !== lo) {
            ctx.fillRect(px(points[i][0]), py(points[i][1]), px(points[i + 1][0]) - px(points[i][0]),
              py(lo) - py(points[i][1]));
          }
        }
        ctx.strokeStyle = "#1f6feb";
        ctx.lineWidth = 2;
        ctx.beginPath();
        ctx.moveTo(px(0), py(s.first));
        for (var j = 1; j < points.length; j++) {
          ctx.lineTo(px(points[j][0]), py(points[j - 1][1]));
          ctx.lineTo(px(points[j][0]), py(points[j][1]));
        }
        ctx.stroke();
        ctx.lineWidth = 1;
        if (hi !== 1 || lo !== 0) {
          ctx.fillStyle = MUTED;
          ctx.font = SMALL;
          ctx.fillText("0 … " + hi, 8, y0 + row / 2 + 18);
        }
      });
    };
    draw();
    return draw;
  }

  // ---- the table: clicking a move highlights it -----------------------------

  function hookTable() {
    var rows = document.querySelectorAll("tr.move");
    Array.prototype.forEach.call(rows, function (tr) {
      tr.addEventListener("click", function () {
        var i = Number(tr.dataset.move);
        selected = selected === i ? -1 : i;
        Array.prototype.forEach.call(rows, function (other) {
          other.classList.toggle("selected", Number(other.dataset.move) === selected);
        });
        draw3d();
        redrawPlots.forEach(function (redraw) {
          redraw();
        });
      });
    });
  }

  function drawAll() {
    sceneBounds();
    resetView(-50, 25);
    draw3d();
    drawLegend();
    hook3d();
    drawPlots();
    redrawPlots.push(drawIo());
    hookTable();
    window.addEventListener("resize", function () {
      draw3d();
      redrawPlots.forEach(function (redraw) {
        redraw();
      });
    });
  }

  try {
    drawAll();
    body.dataset.drawn = "yes";
  } catch (e) {
    console.error("the report could not draw: " + (e && e.stack ? e.stack : e));
  }
})();
