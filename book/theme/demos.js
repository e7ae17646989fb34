// The book's live demos: each chapter's own Rust code, compiled to WebAssembly (the `web`
// crate), driven from here. A page asks for a demo with `<div class="demo" data-demo="NAME">`
// and loads the module with `<script src="demos/web.js"></script>`, which sets
// `window.BOOK_DEMOS_WASM` to the module in base64: a page opened from disk (file://) may run a
// script but not fetch a `.wasm` file, so the module travels inside a script.
//
// The module's exports take and return numbers; results wait in buffers of its memory (a list
// of f64, a UTF-8 text, an image's bytes) read through `numbers_ptr`, `text_ptr` and
// `bytes_ptr`. A panic in the chapter's code (an exercise not written yet) aborts the call: it
// surfaces here as an exception, and the panic's message, kept in a buffer of its own
// (`panic_ptr`), is shown on the demo's canvas.
(function () {
  'use strict';

  let module = null;
  let instance = null;
  // How many times a panic has dropped the instance: a render demo whose sessions lived in a
  // dropped instance starts them again in the new one.
  let resets = 0;

  function wasm() {
    if (instance) return instance;
    if (!module) {
      const base64 = window.BOOK_DEMOS_WASM;
      if (!base64) throw new Error('the demos\' module is missing (demos/web.js did not load)');
      module = new WebAssembly.Module(Uint8Array.from(atob(base64), c => c.charCodeAt(0)));
    }
    instance = new WebAssembly.Instance(module, {}).exports;
    instance.init();
    return instance;
  }

  function text() {
    const m = wasm();
    const bytes = new Uint8Array(m.memory.buffer, m.text_ptr(), m.text_len());
    return new TextDecoder().decode(bytes);
  }

  function numbers() {
    const m = wasm();
    return new Float64Array(m.memory.buffer, m.numbers_ptr(), m.numbers_len()).slice();
  }

  // Calls export `name` with `args`; gives its result, or throws a DemoError carrying the
  // panic's message when the chapter's code panicked (the instance is then dropped: an aborted
  // instance is not to be trusted) or the export refused its arguments (it returns u32::MAX).
  function call(name, ...args) {
    const m = wasm();
    let result;
    try {
      result = m[name](...args) >>> 0;
    } catch (error) {
      let message = '';
      try {
        message = new TextDecoder().decode(new Uint8Array(m.memory.buffer, m.panic_ptr(), m.panic_len()));
      } catch (_) {
        message = String(error);
      }
      instance = null;
      resets += 1;
      throw new DemoError(message || String(error));
    }
    if (result === 0xffffffff) throw new DemoError(text());
    return result;
  }

  class DemoError extends Error {}

  // What a demo shows when the chapter's code stopped: "not written yet: exercise NAME" for a
  // stub, or the panic's message.
  function showFailure(canvas, message) {
    const stub = message.match(/needs (\S+) \(not written yet\)(?:; a hint for it: ([^\n]*))?/);
    const shown = stub
      ? `not written yet: exercise ${stub[1]}` + (stub[2] ? `. Its hint: ${stub[2].trim()}` : '')
      : message;
    const g = canvas.getContext('2d');
    g.fillStyle = '#fff3f0';
    g.fillRect(0, 0, canvas.width, canvas.height);
    g.fillStyle = '#8a1f11';
    g.font = '15px sans-serif';
    const words = shown.split(/\s+/);
    let line = '';
    let y = 30;
    for (const word of words) {
      if (g.measureText(line + word).width > canvas.width - 30) {
        g.fillText(line, 15, y);
        line = '';
        y += 20;
      }
      line += word + ' ';
    }
    g.fillText(line, 15, y);
    canvas.dataset.failure = message;
  }

  function element(tag, attributes, children) {
    const node = document.createElement(tag);
    for (const [key, value] of Object.entries(attributes || {})) {
      if (key === 'text') node.textContent = value;
      else node.setAttribute(key, value);
    }
    for (const child of children || []) node.appendChild(child);
    return node;
  }

  function labelled(text, control) {
    return element('label', { class: 'demo-control' }, [document.createTextNode(text + ' '), control]);
  }

  // ---- Chapter 02: the warp explorer -------------------------------------------------------

  function warpExplorer(root) {
    const count = call('warp_count');
    const names = [];
    for (let i = 0; i < count; i++) { call('warp_name', i); names.push(text()); }

    const warpSelect = element('select', { 'data-control': 'warp' },
      names.map((name, i) => element('option', { value: String(i), text: name })));
    warpSelect.value = String(names.indexOf('disc-naive'));
    const pointsInput = element('input', {
      type: 'range', min: '2', max: '5', step: '0.25', value: '3.5', 'data-control': 'points',
    });
    const pointsShown = element('span', { class: 'demo-value' });
    const exponentInput = element('input', {
      type: 'range', min: '0', max: '100', step: '1', value: '20', 'data-control': 'exponent',
    });
    const exponentShown = element('span', { class: 'demo-value' });
    const viewSelect = element('select', { 'data-control': 'view' }, [
      element('option', { value: 'points', text: 'points' }),
      element('option', { value: 'histogram', text: 'histogram against the density' }),
    ]);
    const seedInput = element('input', { type: 'number', min: '1', value: '1', 'data-control': 'seed' });
    const canvas = element('canvas', { width: '640', height: '320', class: 'demo-canvas' });
    const verdict = element('p', { class: 'demo-verdict', 'aria-live': 'polite' });
    const exponentLabel = labelled('exponent n', exponentInput);
    exponentLabel.appendChild(exponentShown);
    const pointsLabel = labelled('points', pointsInput);
    pointsLabel.appendChild(pointsShown);
    root.append(
      element('div', { class: 'demo-controls' }, [
        labelled('warp', warpSelect), pointsLabel, exponentLabel, labelled('show', viewSelect),
        labelled('seed', seedInput),
      ]),
      canvas, verdict);

    const COLUMNS = 16;
    const ROWS = 16;

    function draw() {
      const index = Number(warpSelect.value);
      const n = Math.round(Math.pow(10, Number(pointsInput.value)));
      const exponent = Number(exponentInput.value);
      const seed = Math.max(1, Math.floor(Number(seedInput.value) || 1));
      const lobe = names[index] === 'cos-lobe';
      exponentLabel.style.display = lobe ? '' : 'none';
      pointsShown.textContent = n.toLocaleString('en');
      exponentShown.textContent = String(exponent);
      delete canvas.dataset.failure;
      const started = performance.now();
      let chi2;
      let points;
      try {
        call('warp_chi2', index, exponent, n, seed, COLUMNS, ROWS);
        chi2 = numbers();
        if (viewSelect.value === 'points') {
          const drawn = Math.min(n, 20000);
          call('warp_points', index, exponent, drawn, seed);
          points = numbers();
        }
      } catch (error) {
        showFailure(canvas, error.message);
        verdict.textContent = '';
        return;
      }
      const g = canvas.getContext('2d');
      g.fillStyle = '#ffffff';
      g.fillRect(0, 0, canvas.width, canvas.height);
      const directions = call('warp_gives_directions', index) === 1;
      const panel = (x0, title) => {
        g.strokeStyle = '#999';
        g.strokeRect(x0 + 10.5, 20.5, 290, 290);
        g.fillStyle = '#333';
        g.font = '13px sans-serif';
        g.fillText(title, x0 + 12, 14);
      };
      const toCanvas = (x0, x, y) => [x0 + 10 + 290 * x, 20 + 290 * (1 - y)];
      if (viewSelect.value === 'points') {
        panel(0, directions ? 'directions over (φ / 2π, (cos θ + 1) / 2)' : 'points');
        g.fillStyle = 'rgba(20, 60, 160, 0.55)';
        for (let i = 0; i < points.length; i += 2) {
          const [x, y] = toCanvas(0, points[i], points[i + 1]);
          g.fillRect(x - 0.75, y - 0.75, 1.5, 1.5);
        }
      } else {
        const observed = chi2.subarray(4, 4 + COLUMNS * ROWS);
        const expected = chi2.subarray(4 + COLUMNS * ROWS);
        let most = 0;
        for (let i = 0; i < observed.length; i++) most = Math.max(most, observed[i], expected[i]);
        const heat = (x0, counts, title) => {
          panel(x0, title);
          for (let row = 0; row < ROWS; row++) {
            for (let column = 0; column < COLUMNS; column++) {
              const value = most > 0 ? counts[row * COLUMNS + column] / most : 0;
              const shade = Math.round(255 * (1 - value));
              g.fillStyle = `rgb(${shade}, ${shade}, 255)`;
              const [x, y] = toCanvas(x0, column / COLUMNS, (row + 1) / ROWS);
              g.fillRect(x, y, 290 / COLUMNS + 0.5, 290 / ROWS + 0.5);
            }
          }
        };
        heat(0, observed, 'observed counts');
        heat(320, expected, 'expected from the claimed density');
      }
      const [statistic, dof, pValue, impossible] = chi2;
      const alpha = 0.01;
      const passes = pValue >= alpha;
      const ms = performance.now() - started;
      verdict.textContent =
        `χ² = ${statistic.toFixed(1)} with ${dof} degrees of freedom` +
        (impossible > 0 ? `, ${impossible} impossible sample(s)` : '') +
        `: p ${pValue > 0 ? '= ' + pValue.toPrecision(3) : '< 1e-300'}, ` +
        (passes ? 'passes' : 'fails') + ` at α = ${alpha} (${n.toLocaleString('en')} samples, ${ms.toFixed(0)} ms)`;
      root.dataset.verdict = passes ? 'passes' : 'fails';
      root.dataset.frames = String(Number(root.dataset.frames || 0) + 1);
    }

    for (const control of [warpSelect, pointsInput, exponentInput, viewSelect, seedInput]) {
      control.addEventListener('input', () => requestAnimationFrame(draw));
    }
    draw();

    // What the controls promise, for the site's check: with 100,000 samples the naive disc
    // fails the test and the polar disc passes it; the lobe's exponent changes the lobe.
    root.demoCheck = async () => {
      const problems = [];
      const show = (name, points) => {
        warpSelect.value = String(names.indexOf(name));
        pointsInput.value = String(points);
        viewSelect.value = 'histogram';
        draw();
        return canvas.dataset.failure === undefined;
      };
      if (!show('disc-naive', 5)) return problems;
      if (root.dataset.verdict !== 'fails') {
        problems.push('the naive disc passed the chi-square test with 100,000 samples');
      }
      if (!show('disc-polar', 5)) return problems;
      if (root.dataset.verdict !== 'passes') {
        problems.push('the polar disc failed the chi-square test with 100,000 samples');
      }
      if (!show('cos-lobe', 3.5)) return problems;
      if (exponentLabel.style.display === 'none') problems.push('the lobe shows no exponent');
      const before = canvas.toDataURL();
      exponentInput.value = exponentInput.value === '3' ? '60' : '3';
      draw();
      if (canvas.dataset.failure === undefined && canvas.toDataURL() === before) {
        problems.push('moving the exponent left the lobe\'s histogram as it was');
      }
      return problems;
    };
  }

  // ---- Chapter 02: the generators' triples in the unit cube --------------------------------
  //
  // Consecutive triples of a generator's numbers as points of the cube, seen from a direction
  // the reader turns (azimuth and elevation), drawn in orthographic projection. With the planes
  // 9x - 6y + z = k seen edge-on, RANDU's points show as a few lines; a good generator's stay a
  // cloud from every side.

  function generatorPlanes(root) {
    const count = call('generator_count');
    const names = [];
    for (let i = 0; i < count; i++) { call('generator_name', i); names.push(text()); }
    const generatorSelect = element('select', { 'data-control': 'generator' },
      names.map((name, i) => element('option', { value: String(i), text: name })));
    const pointsInput = element('input', {
      type: 'range', min: '500', max: '20000', step: '500', value: '6000', 'data-control': 'triples',
    });
    const pointsShown = element('span', { class: 'demo-value' });
    const azimuthInput = element('input', {
      type: 'range', min: '-180', max: '180', step: '0.1', value: '30', 'data-control': 'azimuth',
    });
    const azimuthShown = element('span', { class: 'demo-value' });
    const elevationInput = element('input', {
      type: 'range', min: '-90', max: '90', step: '0.1', value: '20', 'data-control': 'elevation',
    });
    const elevationShown = element('span', { class: 'demo-value' });
    // Directions to look from, as (azimuth, elevation) in degrees. The screen's up is
    // (-sin e cos a, -sin e sin a, cos e): for the planes 9x - 6y + z = k to be seen edge-on, as
    // horizontal lines, it must be their normal.
    const normal = [9, -6, 1];
    const edgeOn = [
      Math.atan2(-normal[1], -normal[0]) * 180 / Math.PI,
      Math.acos(normal[2] / Math.hypot(...normal)) * 180 / Math.PI,
    ].map(angle => Math.round(angle * 10) / 10);
    const presets = [
      ['turned by hand', null],
      ['planes 9x − 6y + z = k edge-on', edgeOn],
      ['down the z axis', [0, 90]],
    ];
    const presetSelect = element('select', { 'data-control': 'look' },
      presets.map(([label], i) => element('option', { value: String(i), text: label })));
    const canvas = element('canvas', { width: '420', height: '420', class: 'demo-canvas' });
    const verdict = element('p', { class: 'demo-verdict', 'aria-live': 'polite' });
    const with_ = (label, input, shown) => { const l = labelled(label, input); l.appendChild(shown); return l; };
    root.append(
      element('div', { class: 'demo-controls' }, [
        labelled('generator', generatorSelect), with_('triples', pointsInput, pointsShown),
        labelled('look', presetSelect),
        with_('azimuth °', azimuthInput, azimuthShown), with_('elevation °', elevationInput, elevationShown),
      ]),
      canvas, verdict);

    function draw() {
      const n = Number(pointsInput.value);
      const azimuth = Number(azimuthInput.value) * Math.PI / 180;
      const elevation = Number(elevationInput.value) * Math.PI / 180;
      pointsShown.textContent = n.toLocaleString('en');
      azimuthShown.textContent = azimuthInput.value;
      elevationShown.textContent = elevationInput.value;
      delete canvas.dataset.failure;
      let triples;
      try {
        call('generator_triples', Number(generatorSelect.value), n, 1);
        triples = numbers();
      } catch (error) {
        if (!(error instanceof DemoError)) throw error;
        showFailure(canvas, error.message);
        verdict.textContent = '';
        return;
      }
      // The screen's axes: right and up, for a viewer looking from direction `view` at the
      // cube's centre.
      const [ca, sa, ce, se] = [Math.cos(azimuth), Math.sin(azimuth), Math.cos(elevation), Math.sin(elevation)];
      const right = [-sa, ca, 0];
      const up = [-se * ca, -se * sa, ce];
      const g = canvas.getContext('2d');
      g.fillStyle = '#ffffff';
      g.fillRect(0, 0, canvas.width, canvas.height);
      const half = canvas.width / 2;
      const scale = canvas.width / 1.8;
      const project = (x, y, z) => {
        const q = [x - 0.5, y - 0.5, z - 0.5];
        return [
          half + scale * (q[0] * right[0] + q[1] * right[1] + q[2] * right[2]),
          half - scale * (q[0] * up[0] + q[1] * up[1] + q[2] * up[2]),
        ];
      };
      g.strokeStyle = '#bbb';
      g.beginPath();
      for (const [a, b] of [[0, 1], [1, 3], [3, 2], [2, 0], [4, 5], [5, 7], [7, 6], [6, 4], [0, 4], [1, 5], [2, 6], [3, 7]]) {
        const corner = i => [i & 1, (i >> 1) & 1, (i >> 2) & 1];
        g.moveTo(...project(...corner(a)));
        g.lineTo(...project(...corner(b)));
      }
      g.stroke();
      g.fillStyle = 'rgba(20, 60, 160, 0.6)';
      for (let i = 0; i + 2 < triples.length - 1; i += 3) {
        const [x, y] = project(triples[i], triples[i + 1], triples[i + 2]);
        g.fillRect(x - 0.7, y - 0.7, 1.4, 1.4);
      }
      const share = triples[triples.length - 1];
      verdict.textContent =
        `${names[Number(generatorSelect.value)]}: ${(100 * share).toFixed(share > 0.01 ? 1 : 4)} % of ` +
        `${n.toLocaleString('en')} triples (x, y, z) within 10⁻⁶ of a plane 9x − 6y + z = integer`;
      root.dataset.share = String(share);
      root.dataset.frames = String(Number(root.dataset.frames || 0) + 1);
    }

    presetSelect.addEventListener('input', () => {
      const preset = presets[Number(presetSelect.value)][1];
      if (preset) [azimuthInput.value, elevationInput.value] = preset.map(String);
      requestAnimationFrame(draw);
    });
    for (const input of [azimuthInput, elevationInput]) {
      input.addEventListener('input', () => { presetSelect.value = '0'; requestAnimationFrame(draw); });
    }
    for (const input of [generatorSelect, pointsInput]) {
      input.addEventListener('input', () => requestAnimationFrame(draw));
    }
    draw();

    // What the controls promise: every RANDU triple lies on one of its planes, few of a
    // good generator's do; and with the planes edge-on, RANDU's points crowd onto a few lines
    // across the screen, which a good generator's do not.
    root.demoCheck = async () => {
      const problems = [];
      const pick = name => { generatorSelect.value = String(names.indexOf(name)); };
      presetSelect.value = '1';
      presetSelect.dispatchEvent(new Event('input'));
      const rowsFilled = () => {
        const image = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data;
        let rows = 0;
        for (let y = 0; y < canvas.height; y++) {
          let inked = 0;
          for (let x = 0; x < canvas.width; x++) {
            const at = 4 * (y * canvas.width + x);
            if (image[at + 2] > 120 && image[at] < 150) inked++;
          }
          if (inked > 3) rows++;
        }
        return rows;
      };
      pick('randu');
      draw();
      if (canvas.dataset.failure !== undefined) return problems;
      const randuRows = rowsFilled();
      if (Number(root.dataset.share) !== 1) problems.push(`only ${root.dataset.share} of RANDU's triples lie on its planes`);
      pick('pcg32');
      draw();
      const pcgRows = rowsFilled();
      if (Number(root.dataset.share) > 0.01) problems.push(`${root.dataset.share} of PCG32's triples lie on RANDU's planes`);
      if (!(randuRows < pcgRows / 2)) {
        problems.push(`with the planes edge-on, RANDU's points cover ${randuRows} rows of pixels and PCG32's ${pcgRows}: RANDU's should crowd onto a few lines`);
      }
      return problems;
    };
  }

  // ---- Every other chapter: a render refined one sample per pixel at a time ---------------
  //
  // The module describes the demo (its controls, views and claims, `demo_spec`); the page
  // builds the controls, starts every view with their values (`demo_start`), and on each
  // animation frame gives each unfinished view an equal share of about 14 ms of tracing
  // (`demo_advance`, in whole rows; the rows per millisecond are measured as it goes), then
  // draws the films (`demo_image`). Views side by side get equal time: all stop when the first
  // reaches its samples per pixel, so the slower technique shows fewer.

  function writeText(value) {
    const bytes = new TextEncoder().encode(value);
    const m = wasm();
    const at = m.input_text_ptr(bytes.length);
    new Uint8Array(m.memory.buffer, at, bytes.length).set(bytes);
  }

  function writeNumbers(values) {
    const m = wasm();
    const at = m.input_numbers_ptr(values.length);
    new Float64Array(m.memory.buffer, at, values.length).set(values);
  }

  function bytes(length) {
    const m = wasm();
    return new Uint8ClampedArray(m.memory.buffer, m.bytes_ptr(), length).slice();
  }

  const FRAME_MS = 14;
  // Each view of each demo on the page refines in a slot of its own in the module.
  let slots = 0;

  function renderDemo(root) {
    root.dataset.progressive = 'yes';
    writeText(root.dataset.demo);
    const index = call('demo_find');
    call('demo_spec', index);
    const spec = JSON.parse(text());
    const width = spec.width;
    const height = spec.height;
    const views = spec.views.length;
    root.dataset.size = `${width} x ${height}`;
    const firstSlot = slots;
    slots += views;

    const controls = spec.controls.map(control => {
      let input;
      const shown = element('span', { class: 'demo-value' });
      if (control.options) {
        input = element('select', { 'data-control': control.name },
          control.options.map((option, i) => element('option', { value: String(i), text: option })));
      } else {
        input = element('input', {
          type: 'range', min: String(control.min), max: String(control.max),
          step: String(control.step), 'data-control': control.name,
        });
      }
      input.value = String(control.value);
      const label = labelled(control.label, input);
      if (!control.options) label.appendChild(shown);
      const show = () => { shown.textContent = input.value; };
      show();
      return { control, input, label, show };
    });
    // A control that matters only for one value of another (a polygon's blades) hides
    // otherwise.
    const showRelevant = () => {
      for (const { control, label } of controls) {
        if (!control.when) continue;
        const other = controls.find(c => c.control.name === control.when.name);
        label.style.display = other && Number(other.input.value) === control.when.value ? '' : 'none';
      }
    };
    showRelevant();
    let zoom = null;
    const extra = [];
    if (spec.zoom) {
      zoom = element('select', { 'data-control': 'zoom' },
        [1, 2, 4, 8].map(z => element('option', { value: String(z), text: z === 1 ? 'whole image' : `${z}× on the centre` })));
      extra.push(labelled('zoom', zoom));
    }
    const scale = 2;
    const gap = 12;
    const canvas = element('canvas', {
      width: String(views * width * scale + (views - 1) * gap),
      height: String(height * scale + (views > 1 || spec.views[0] ? 20 : 0)),
      class: 'demo-canvas',
    });
    const status = element('p', { class: 'demo-verdict', 'aria-live': 'polite' });
    root.append(
      element('div', { class: 'demo-controls' }, [...controls.map(c => c.label), ...extra]),
      canvas, status);

    const film = element('canvas', { width: String(width), height: String(height) });
    let state = null;

    function fail(error) {
      if (!(error instanceof DemoError)) throw error;
      showFailure(canvas, error.message);
      status.textContent = '';
      state = null;
    }

    function draw() {
      const g = canvas.getContext('2d');
      g.fillStyle = '#ffffff';
      g.fillRect(0, 0, canvas.width, canvas.height);
      const top = canvas.height - height * scale;
      const z = zoom ? Number(zoom.value) : 1;
      for (let view = 0; view < views; view++) {
        const length = call('demo_image', firstSlot + view);
        film.getContext('2d').putImageData(new ImageData(bytes(length), width, height), 0, 0);
        const x0 = view * (width * scale + gap);
        g.imageSmoothingEnabled = false;
        const w = width / z;
        const h = height / z;
        g.drawImage(film, (width - w) / 2, (height - h) / 2, w, h, x0, top, width * scale, height * scale);
        if (top > 0 && state) {
          g.fillStyle = '#333';
          g.font = '13px sans-serif';
          g.fillText(`${spec.views[view]}: ${state.spp[view]} spp, ${(state.ms[view] / 1000).toFixed(2)} s`, x0 + 2, 14);
        }
      }
      root.dataset.frames = String(Number(root.dataset.frames || 0) + 1);
    }

    function report() {
      const spp = Math.min(...state.spp);
      const ms = performance.now() - state.started;
      status.textContent = views > 1
        ? `equal time: ${spec.views.map((v, i) => `${v} ${state.spp[i]} spp`).join(', ')} (${(ms / 1000).toFixed(2)} s)`
        : `${spp} of ${state.target[0]} samples per pixel, ${width} × ${height}, ${(ms / 1000).toFixed(2)} s`;
      root.dataset.spp = String(spp);
    }

    // A demo refines only while it is on screen: the print page holds every demo at once.
    let visible = false;
    let scheduled = false;
    function schedule() {
      if (scheduled || !visible || !state || state.finished) return;
      scheduled = true;
      const generation = state.generation;
      requestAnimationFrame(() => { scheduled = false; frame(generation); });
    }
    new IntersectionObserver(entries => {
      visible = entries.some(entry => entry.isIntersecting);
      schedule();
    }).observe(root);

    function frame(generation) {
      if (!state || state.finished || state.generation !== generation) return;
      // Another demo's panic dropped the module's instance, and this demo's sessions with it.
      if (state.resets !== resets) { restart(); return; }
      // A demo started off screen waits for the reader: its clock starts when it first runs.
      if (!state.running) {
        state.running = true;
        if (!state.visibleAtStart) state.started = performance.now();
      }
      try {
        const share = FRAME_MS / views;
        for (let view = 0; view < views; view++) {
          if (state.spp[view] >= state.target[view]) continue;
          const budget = Math.max(width, Math.round(state.rate[view] * share));
          const t0 = performance.now();
          const traced = call('demo_advance', firstSlot + view, budget);
          const dt = Math.max(performance.now() - t0, 0.05);
          state.rate[view] = traced / dt;
          state.ms[view] += dt;
          state.spp[view] = call('demo_spp', firstSlot + view);
        }
      } catch (error) {
        fail(error);
        return;
      }
      const now = performance.now() - state.started;
      const done = views > 1
        ? state.spp.some((spp, view) => spp >= state.target[view])
        : state.spp[0] >= state.target[0];
      draw();
      report();
      if (root.dataset.firstFrameMs === undefined) root.dataset.firstFrameMs = now.toFixed(1);
      if (root.dataset.firstPassMs === undefined && Math.min(...state.spp) >= 1) {
        root.dataset.firstPassMs = now.toFixed(1);
      }
      if (done) {
        root.dataset.doneMs = now.toFixed(1);
        root.dataset.done = 'yes';
        state.finished = true;
      } else {
        schedule();
      }
    }

    let generations = 0;
    // The site's check refines to fewer samples per pixel (`demoCap`): it needs to see a
    // control change the picture, not a converged one.
    let cap = Infinity;
    function restart() {
      delete canvas.dataset.failure;
      for (const key of ['firstFrameMs', 'firstPassMs', 'doneMs', 'done']) delete root.dataset[key];
      for (const control of controls) control.show();
      showRelevant();
      const values = controls.map(control => Number(control.input.value));
      generations += 1;
      state = {
        generation: generations, started: performance.now(), visibleAtStart: visible, running: false,
        target: [], spp: Array(views).fill(0), ms: Array(views).fill(0), rate: Array(views).fill(0),
      };
      try {
        wasm();
        state.resets = resets;
        for (let view = 0; view < views; view++) {
          writeNumbers(values);
          state.target.push(Math.min(cap, call('demo_start', index, view, firstSlot + view, width, height)));
        }
      } catch (error) {
        fail(error);
        return;
      }
      scheduled = false;
      schedule();
    }
    root.demoRestart = restart;
    root.demoCap = samples => { cap = samples; restart(); };

    for (const control of controls) control.input.addEventListener('input', restart);
    if (zoom) {
      zoom.addEventListener('input', () => {
        if (!state || canvas.dataset.failure) return;
        if (state.resets !== resets) { restart(); return; }
        try { draw(); } catch (error) { fail(error); }
      });
    }
    restart();

    // What the controls promise, for the site's check: the demo's claims, each checked by the
    // module on small renders of the chapter's code.
    root.demoCheck = async () => {
      const problems = [];
      for (let claim = 0; claim < spec.claims.length; claim++) {
        try {
          call('demo_claim', index, claim);
        } catch (error) {
          if (!(error instanceof DemoError)) throw error;
          if (error.message.includes('(not written yet)')) {
            showFailure(canvas, error.message);
            return problems;
          }
          problems.push(error.message);
        }
      }
      return problems;
    };
  }

  const DEMOS = { warps: warpExplorer, generators: generatorPlanes };

  for (const root of document.querySelectorAll('div.demo[data-demo]')) {
    const demo = DEMOS[root.dataset.demo] || renderDemo;
    try {
      demo(root);
      root.dataset.ready = 'yes';
    } catch (error) {
      const canvas = root.querySelector('canvas') ||
        root.appendChild(element('canvas', { width: '640', height: '120', class: 'demo-canvas' }));
      showFailure(canvas, error.message);
      root.dataset.ready = 'failed';
      console.warn(error);
    }
  }
})();
