// The probe of tests/browser/iridescence_page_test.py, run inside the gallery's iridescence.html
// (opened from file://): waits for the page's first frames, measures the canvas' two halves
// (irid's on the left, three.js's stock on the right), moves a slider as a person would (its
// value and an 'input' event) and measures again, then puts the slider back.
//
// input: {frames: frames to wait for, slider: the <input> id, value: the value to move it to,
//         timeoutMs}
// returns: {frames, width, height, before: {left, right}, after: {left, right}, restored:
//          {left, right}, change: {left, right}, between: {before}}: per half, stats {mean:
//          [r, g, b], stdLuma, colours: distinct colours at 5 bits a channel, lit: fraction of
//          pixels brighter than the background}; change: mean |Δ| (0–255, over RGB) of each half
//          between before and after; between: mean |Δ| of the left half against the right.

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

function halfStats(image, left) {
    const { width, height, data } = image;
    const half = Math.floor(width / 2);
    const [x0, x1] = left ? [0, half] : [half, width];
    const background = [data[0], data[1], data[2]];
    const sum = [0, 0, 0];
    let luma = 0;
    let luma2 = 0;
    let lit = 0;
    const colours = new Set();
    for (let y = 0; y < height; ++y) {
        for (let x = x0; x < x1; ++x) {
            const i = 4 * (y * width + x);
            const [r, g, b] = [data[i], data[i + 1], data[i + 2]];
            sum[0] += r;
            sum[1] += g;
            sum[2] += b;
            const l = 0.2126 * r + 0.7152 * g + 0.0722 * b;
            luma += l;
            luma2 += l * l;
            if (r + g + b > background[0] + background[1] + background[2] + 24) ++lit;
            colours.add(((r >> 3) << 10) | ((g >> 3) << 5) | (b >> 3));
        }
    }
    const n = (x1 - x0) * height;
    return { mean: sum.map((s) => s / n), stdLuma: Math.sqrt(Math.max(0, luma2 / n - (luma / n) ** 2)),
             colours: colours.size, lit: lit / n };
}

// Mean |Δ| over RGB between two regions of equal width (0–255).
function difference(a, ax, b, bx, width) {
    let sum = 0;
    for (let y = 0; y < a.height; ++y) {
        for (let x = 0; x < width; ++x) {
            const i = 4 * (y * a.width + ax + x);
            const j = 4 * (y * b.width + bx + x);
            sum += Math.abs(a.data[i] - b.data[j]) + Math.abs(a.data[i + 1] - b.data[j + 1]) +
                   Math.abs(a.data[i + 2] - b.data[j + 2]);
        }
    }
    return sum / (3 * a.height * width);
}

function both(image) {
    return { left: halfStats(image, true), right: halfStats(image, false) };
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
    const slider = document.getElementById(input.slider);
    if (!slider) throw new Error(`the page has no slider #${input.slider}`);
    const initial = slider.value;
    move(slider, input.value);
    await nextFrame(input.timeoutMs);
    const after = pixels();
    move(slider, initial);
    await nextFrame(input.timeoutMs);
    const restored = pixels();
    const half = Math.floor(before.width / 2);
    const rightWidth = before.width - half;
    return {
        frames: framesDrawn(), width: before.width, height: before.height,
        before: both(before), after: both(after), restored: both(restored),
        change: { left: difference(before, 0, after, 0, half), right: difference(before, half, after, half, rightWidth) },
        between: { before: difference(before, 0, before, half, Math.min(half, rightWidth)) },
        restoredChange: { left: difference(before, 0, restored, 0, half) },
    };
}
