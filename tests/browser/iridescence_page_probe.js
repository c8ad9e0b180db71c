// The probe of tests/browser/iridescence_page_test.py, run inside the gallery's iridescence.html
// (opened from file://): waits for the page's first frames, measures the canvas' two halves
// (irid's and three.js's stock: left and right side by side, top and bottom stacked, as the page's
// data-layout says), moves a slider as a person would (its value and an 'input' event) and
// measures again, then puts the slider back; last, it puts the camera under the water and lets
// the controls update.
//
// input: {frames: frames to wait for, slider: the <input> id, value: the value to move it to,
//         timeoutMs}
// returns: {frames, width, height, layout, before: {irid, stock}, after: {irid, stock}, restored:
//          {irid, stock}, change: {irid, stock}, between: {before}, restoredChange: {irid},
//          cameraY: the camera's height after the controls' update}: per half, stats {mean:
//          [r, g, b], stdLuma, colours: distinct colours at 5 bits a channel, lit: fraction of
//          pixels brighter than the darkest 1 % of the half}; change: mean |Δ| (0–255, over RGB)
//          of each half between before and after; between: mean |Δ| of the two halves.

function framesDrawn() {
    return Number(document.body.dataset.frames || 0);
}

async function waitFor(condition, timeoutMs, what) {
    const start = performance.now();
    while (!condition()) {
        if (performance.now() - start > timeoutMs) throw new Error(`timed out waiting for ${what}`);
        await new Promise((resolve) => setTimeout(resolve, 50));
    }
}

function pixels() {
    const canvas = document.querySelector('#view canvas');
    if (!canvas) throw new Error('the page has no canvas in #view');
    const copy = document.createElement('canvas');
    copy.width = canvas.width;
    copy.height = canvas.height;
    const context = copy.getContext('2d');
    context.drawImage(canvas, 0, 0);
    return { width: copy.width, height: copy.height, data: context.getImageData(0, 0, copy.width, copy.height).data };
}

// The halves' rectangles in the canvas' pixels (rows from the top): irid's first.
function halves(width, height) {
    if (document.body.dataset.layout === 'stacked') {
        const top = height - Math.floor(height / 2);
        return { irid: [0, 0, width, top], stock: [0, top, width, height - top] };
    }
    const half = Math.floor(width / 2);
    return { irid: [0, 0, half, height], stock: [half, 0, width - half, height] };
}

function halfStats(image, [x0, y0, w, h]) {
    const { width, data } = image;
    const sum = [0, 0, 0];
    let luma = 0;
    let luma2 = 0;
    const lumas = [];
    const colours = new Set();
    for (let y = y0; y < y0 + h; ++y) {
        for (let x = x0; x < x0 + w; ++x) {
            const i = 4 * (y * width + x);
            const [r, g, b] = [data[i], data[i + 1], data[i + 2]];
            sum[0] += r;
            sum[1] += g;
            sum[2] += b;
            const l = 0.2126 * r + 0.7152 * g + 0.0722 * b;
            luma += l;
            luma2 += l * l;
            lumas.push(l);
            colours.add(((r >> 3) << 10) | ((g >> 3) << 5) | (b >> 3));
        }
    }
    const n = w * h;
    lumas.sort((a, b) => a - b);
    const dark = lumas[Math.floor(0.01 * n)];
    const lit = lumas.filter((l) => l > dark + 8).length;
    return { mean: sum.map((s) => s / n), stdLuma: Math.sqrt(Math.max(0, luma2 / n - (luma / n) ** 2)),
             colours: colours.size, lit: lit / n };
}

// Mean |Δ| over RGB between two rectangles of equal size (0–255).
function difference(a, [ax, ay, w, h], b, [bx, by]) {
    let sum = 0;
    for (let y = 0; y < h; ++y) {
        for (let x = 0; x < w; ++x) {
            const i = 4 * ((ay + y) * a.width + ax + x);
            const j = 4 * ((by + y) * b.width + bx + x);
            sum += Math.abs(a.data[i] - b.data[j]) + Math.abs(a.data[i + 1] - b.data[j + 1]) +
                   Math.abs(a.data[i + 2] - b.data[j + 2]);
        }
    }
    return sum / (3 * w * h);
}

function both(image, rects) {
    return { irid: halfStats(image, rects.irid), stock: halfStats(image, rects.stock) };
}

async function nextFrame(timeoutMs) {
    const seen = framesDrawn();
    await waitFor(() => framesDrawn() > seen, timeoutMs, 'a frame after the slider moved');
}

function move(slider, value) {
    slider.value = String(value);
    slider.dispatchEvent(new Event('input', { bubbles: true }));
}

export async function run(input) {
    await waitFor(() => framesDrawn() >= input.frames, input.timeoutMs, `${input.frames} frames`);
    const before = pixels();
    const rects = halves(before.width, before.height);
    const slider = document.getElementById(input.slider);
    if (!slider) throw new Error(`the page has no slider #${input.slider}`);
    const initial = slider.value;
    move(slider, input.value);
    await nextFrame(input.timeoutMs);
    const after = pixels();
    move(slider, initial);
    await nextFrame(input.timeoutMs);
    const restored = pixels();
    // The smaller of the two halves' sizes, for the comparison between them.
    const common = [0, 0, Math.min(rects.irid[2], rects.stock[2]), Math.min(rects.irid[3], rects.stock[3])];
    const out = {
        frames: framesDrawn(), width: before.width, height: before.height, layout: document.body.dataset.layout,
        before: both(before, rects), after: both(after, rects), restored: both(restored, rects),
        change: { irid: difference(before, rects.irid, after, rects.irid),
                  stock: difference(before, rects.stock, after, rects.stock) },
        between: { before: difference(before, [rects.irid[0], rects.irid[1], common[2], common[3]],
                                      before, rects.stock) },
        restoredChange: { irid: difference(before, rects.irid, restored, rects.irid) },
    };
    // Under the water: the controls must bring the camera back above it.
    const { camera, controls } = window.iridPage;
    camera.position.set(controls.target.x, -3, controls.target.z + 4);
    controls.update();
    out.cameraY = camera.position.y;
    // The view as it was, for the screenshot.
    camera.position.set(0.0, 3.4, 7.6);
    controls.update();
    await nextFrame(input.timeoutMs);
    return out;
}
