// The live preview: frames from the real renderer, orbit or fly with the mouse, mono or side-by-side
// stereo, the frame's GPU time and evaluations per pixel, and the probe under a clicked pixel.
import { useRef, useState } from "react";
import { REFINED_SAMPLES, type FrameInfo, type ProbeInfo } from "./api";
import { dolly, fly, look, orbit, type Camera } from "./camera";

interface Props {
  frame: FrameInfo | null;
  camera: Camera;
  onCamera: (c: Camera) => void;
  stereo: boolean;
  onStereo: (s: boolean) => void;
  probe: ProbeInfo | null;
  onProbe: (x: number, y: number) => void;
  status: string;
}

export function Preview({ frame, camera, onCamera, stereo, onStereo, probe, onProbe, status }: Props) {
  const [mode, setMode] = useState<"orbit" | "fly">("orbit");
  const drag = useRef<{ x: number; y: number; moved: boolean } | null>(null);
  const fmt = (x: number) => x.toFixed(3);
  return (
    <div className="preview">
      <div className="preview-bar">
        <button className={mode === "orbit" ? "on" : ""} onClick={() => setMode("orbit")}>orbit</button>
        <button className={mode === "fly" ? "on" : ""} onClick={() => setMode("fly")} title="drag to look, W A S D Q E to move">fly</button>
        <button className={stereo ? "" : "on"} onClick={() => onStereo(false)} data-testid="mono">mono</button>
        <button className={stereo ? "on" : ""} onClick={() => onStereo(true)} data-testid="stereo">side by side</button>
      </div>
      <div
        className="preview-frame"
        tabIndex={0}
        data-testid="preview-frame"
        onKeyDown={(e) => {
          if (mode !== "fly") return;
          const moves: Record<string, [number, number, number]> = { w: [1, 0, 0], s: [-1, 0, 0], a: [0, -1, 0], d: [0, 1, 0], q: [0, 0, -1], e: [0, 0, 1] };
          const m = moves[e.key.toLowerCase()];
          if (m) onCamera(fly(camera, ...m));
        }}
        onWheel={(e) => onCamera(mode === "orbit" ? dolly(camera, e.deltaY > 0 ? 1.1 : 1 / 1.1) : fly(camera, e.deltaY > 0 ? -1 : 1, 0, 0))}
        onPointerDown={(e) => {
          drag.current = { x: e.clientX, y: e.clientY, moved: false };
          (e.target as HTMLElement).setPointerCapture(e.pointerId);
        }}
        onPointerMove={(e) => {
          const d = drag.current;
          if (!d) return;
          const dx = e.clientX - d.x, dy = e.clientY - d.y;
          if (!d.moved && Math.hypot(dx, dy) < 3) return;
          d.moved = true;
          d.x = e.clientX;
          d.y = e.clientY;
          onCamera(mode === "orbit" ? orbit(camera, dx, dy) : look(camera, dx, dy));
        }}
        onPointerUp={(e) => {
          const d = drag.current;
          drag.current = null;
          if (!d || d.moved || !frame) return;
          const img = (e.currentTarget as HTMLElement).querySelector("img");
          if (!img) return;
          const rect = img.getBoundingClientRect();
          const eyeWidth = stereo ? frame.width / 2 : frame.width;
          const x = Math.floor(((e.clientX - rect.left) / rect.width) * frame.width);
          const y = Math.floor(((e.clientY - rect.top) / rect.height) * frame.height);
          if (x >= 0 && y >= 0 && x < eyeWidth && y < frame.height) onProbe(x, y);
        }}
      >
        {frame ? <img src={frame.url} alt="preview" data-testid="preview-image" draggable={false} /> : <div className="muted">waiting for the first frame…</div>}
      </div>
      <div className="stats" data-testid="stats">
        {frame && (
          <>
            <span>GPU {frame.gpuMs >= 0 ? `${frame.gpuMs.toFixed(1)} ms` : "n/a"}</span>
            <span>frame {frame.cpuMs.toFixed(1)} ms</span>
            <span>{frame.evaluationsPerPixel.toFixed(1)} evaluations/pixel</span>
            <span data-testid="samples">
              {frame.samples >= REFINED_SAMPLES ? `${frame.samples} samples/pixel` : `refining: ${frame.samples}/${REFINED_SAMPLES} samples`}
            </span>
            <span data-testid="compiles">{frame.compiles} compiles</span>
          </>
        )}
        <span className="status" data-testid="status">{status}</span>
      </div>
      {probe && (
        <div className="probe" data-testid="probe">
          {probe.hit ? (
            <>
              hit at ({fmt(probe.point[0])}, {fmt(probe.point[1])}, {fmt(probe.point[2])}), {fmt(probe.depth)} from the eye; distance
              there {probe.distance.toExponential(2)}
            </>
          ) : (
            <>no surface under that pixel</>
          )}
        </div>
      )}
    </div>
  );
}
