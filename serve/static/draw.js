// Draw a dungeon from above on a canvas: rows are z (north at the top), columns x.
// A cell shows the top block of its column; a column that reaches the agent's feet
// is an obstacle (wall, stone) and is drawn raised. Rooms are tinted outlines, other
// objects a lettered disc, the agent a disc with an arrow for its facing.

const BLOCK_COLORS = {
  bedrock: ["#9a9a9a", "#3d3d3d"],      // [floor, raised]
  lava: ["#ff5a1f", "#c73a0b"],
  gold: ["#ffd21f", "#d4a600"],
  burlap_stone: ["#b08a5a", "#7a5a32"],
  red_wool: ["#e05050", "#a52a2a"],
  orange_wool: ["#f5a040", "#c06a10"],
  green_wool: ["#5cbf5c", "#2e7d32"],
  blue_wool: ["#5a7fe0", "#2a4aa5"],
  air: ["#141414", "#141414"],
};
const ROOM_COLORS = { red: "#ff4040", orange: "#ff9a1a", green: "#30c030", blue: "#4060ff" };
export const AGENT_COLOR = "#1f6fff";
const FACING_VECTORS = { north: [0, -1], south: [0, 1], east: [1, 0], west: [-1, 0] };

function hashColor(name) {
  let h = 0;
  for (const ch of name) h = (h * 31 + ch.charCodeAt(0)) % 360;
  return [`hsl(${h} 45% 60%)`, `hsl(${h} 45% 35%)`];
}

export function blockColor(name, raised) {
  const pair = BLOCK_COLORS[name] || hashColor(name);
  return pair[raised ? 1 : 0];
}

export function cellSize(scene, maxPixels = 640) {
  return Math.max(6, Math.min(48, Math.floor(maxPixels / Math.max(scene.width, scene.depth))));
}

// The columns of a frame: the scene's start columns with the frame's changes applied.
export function frameColumns(scene, frame) {
  const cols = scene.columns.map((row) => row.slice());
  for (const [x, z, column] of frame.changed) cols[z][x] = column;
  return cols;
}

export function draw(canvas, scene, frame, path = []) {
  const size = cellSize(scene);
  canvas.width = scene.width * size;
  canvas.height = scene.depth * size;
  canvas.dataset.cell = String(size);
  const ctx = canvas.getContext("2d");
  const cols = frameColumns(scene, frame);
  const feet = frame.agent[1];
  for (let z = 0; z < scene.depth; z++) {
    for (let x = 0; x < scene.width; x++) {
      const column = cols[z][x];
      const top = column.length ? scene.blocks[column[column.length - 1]] : "air";
      const raised = column.length > feet;
      ctx.fillStyle = blockColor(top, raised);
      ctx.fillRect(x * size, z * size, size, size);
      if (raised) {   // a bevel, so obstacles read as standing up
        ctx.fillStyle = "rgba(255,255,255,0.18)";
        ctx.fillRect(x * size, z * size, size, Math.max(2, size / 8));
      }
      ctx.strokeStyle = "rgba(0,0,0,0.25)";
      ctx.strokeRect(x * size + 0.5, z * size + 0.5, size - 1, size - 1);
    }
  }
  for (const room of scene.rooms) {
    const color = ROOM_COLORS[room.color] || room.color || "#ffffff";
    const [x0, x1] = room.x, [z0, z1] = room.z;
    ctx.fillStyle = color;
    ctx.globalAlpha = 0.12;
    ctx.fillRect(x0 * size, z0 * size, (x1 - x0 + 1) * size, (z1 - z0 + 1) * size);
    ctx.globalAlpha = 0.9;
    ctx.lineWidth = 2;
    ctx.strokeStyle = color;
    ctx.strokeRect(x0 * size + 2, z0 * size + 2, (x1 - x0 + 1) * size - 4, (z1 - z0 + 1) * size - 4);
    ctx.globalAlpha = 1;
    ctx.lineWidth = 1;
    ctx.fillStyle = "#fff";
    ctx.font = `${Math.max(9, size / 3)}px sans-serif`;
    ctx.fillText(room.name, x0 * size + 5, z0 * size + Math.max(11, size / 2.5));
  }
  // The path walked so far: small dots at the centre of each visited cell.
  ctx.fillStyle = "rgba(255,255,255,0.75)";
  for (const [x, , z] of path) {
    ctx.beginPath();
    ctx.arc((x + 0.5) * size, (z + 0.5) * size, Math.max(1.5, size / 10), 0, 2 * Math.PI);
    ctx.fill();
  }
  for (const obj of scene.objects) {
    disc(ctx, obj.x, obj.z, size, "#f0e6c8", obj.name[0].toUpperCase());
  }
  const [ax, , az] = frame.agent;
  disc(ctx, ax, az, size, frame.failure ? "#000" : AGENT_COLOR, null);
  const v = FACING_VECTORS[frame.facing];
  if (v) {   // an arrow from the centre towards the facing
    const cx = (ax + 0.5) * size, cz = (az + 0.5) * size, r = size * 0.42;
    const px = -v[1], pz = v[0];
    ctx.fillStyle = "#fff";
    ctx.beginPath();
    ctx.moveTo(cx + v[0] * r, cz + v[1] * r);
    ctx.lineTo(cx + px * r * 0.45 - v[0] * r * 0.1, cz + pz * r * 0.45 - v[1] * r * 0.1);
    ctx.lineTo(cx - px * r * 0.45 - v[0] * r * 0.1, cz - pz * r * 0.45 - v[1] * r * 0.1);
    ctx.closePath();
    ctx.fill();
  }
  if (frame.variables["agent.verticalDirection"] === 1) {   // looking down: a ring
    ctx.strokeStyle = "#fff";
    ctx.lineWidth = 2;
    ctx.beginPath();
    ctx.arc((ax + 0.5) * size, (az + 0.5) * size, size * 0.46, 0, 2 * Math.PI);
    ctx.stroke();
    ctx.lineWidth = 1;
  }
}

// The block names a scene shows on top of some column, for the legend beside the canvas.
export function topBlocks(scene) {
  const seen = new Set();
  for (const row of scene.columns) for (const column of row) {
    seen.add(column.length ? scene.blocks[column[column.length - 1]] : "air");
  }
  return [...seen].sort();
}

function disc(ctx, x, z, size, color, letter) {
  ctx.fillStyle = color;
  ctx.beginPath();
  ctx.arc((x + 0.5) * size, (z + 0.5) * size, size * 0.4, 0, 2 * Math.PI);
  ctx.fill();
  if (letter) {
    ctx.fillStyle = "#222";
    ctx.font = `bold ${Math.max(9, size / 2)}px sans-serif`;
    ctx.textAlign = "center";
    ctx.textBaseline = "middle";
    ctx.fillText(letter, (x + 0.5) * size, (z + 0.5) * size);
    ctx.textAlign = "start";
    ctx.textBaseline = "alphabetic";
  }
}
