'use strict'
// bcc's bridge to a real Minecraft world: one long-lived Node process that runs a
// flying-squid server in-process and, on request, a mineflayer bot that joins it.
//
// Python (minecraft/bridge.py) talks to it in JSON lines: requests {"id", "op", ...} on
// stdin, replies {"id", "ok", "result" | "error"} and events {"event", ...} on stdout.
// Everything else (the server's console, logs, warnings) goes to stderr, and the
// server's own command console is kept off stdin (it would swallow our requests).
//
// The bridge is deliberately dumb about bcc's rules: Python checks every action with
// the compiled model first and tells the bridge the geometry (which cell to walk to,
// which block to dig, which face to click). The bridge executes it with the bot and
// reports when the server's world has settled. What the server itself does not do the
// bcc way (drops and pick-up of mined blocks) the bridge does, in `onDug` below.

const readline = require('readline')
const { PassThrough } = require('stream')

const jsonIn = process.stdin
const jsonOut = process.stdout
// flying-squid opens a readline console on process.stdin/stdout when it is loaded: give
// it a dead input and stderr instead, before requiring it.
Object.defineProperty(process, 'stdin', { value: new PassThrough(), configurable: true })
Object.defineProperty(process, 'stdout', { value: process.stderr, configurable: true })
console.log = (...args) => console.error(...args)
console.info = (...args) => console.error(...args)

const { Vec3 } = require('vec3')

let flyingSquid = null
let mineflayer = null
let serv = null
let registry = null
let Item = null
let settings = { version: '1.16.5', port: 25565, host: '127.0.0.1' }
let rules = { mineable: [], origin: [0, 64, 0], size: [0, 0, 0] }
const bots = {}
const persons = new Set() // bots that stand in for a person (tests): handled like people

function send (msg) {
  jsonOut.write(JSON.stringify(msg) + '\n')
}

function sleep (ms) {
  return new Promise(resolve => setTimeout(resolve, ms))
}

function withTimeout (promise, ms, what) {
  let timer
  return Promise.race([
    promise,
    new Promise((resolve, reject) => {
      timer = setTimeout(() => reject(new Error(`${what} did not finish within ${ms} ms`)), ms)
    })
  ]).finally(() => clearTimeout(timer))
}

async function until (test, ms, what, step = 25) {
  const end = Date.now() + ms
  while (Date.now() < end) {
    if (await test()) return
    await sleep(step)
  }
  throw new Error(`${what} did not happen within ${ms} ms`)
}

// ---- server -------------------------------------------------------------------------

async function start ({ port, version, host }) {
  if (serv) throw new Error('the server is already running')
  settings = { ...settings, port, version: version || settings.version, host: host || settings.host }
  flyingSquid = require('flying-squid')
  serv = flyingSquid.createMCServer({
    motd: 'bcc dungeon',
    port: settings.port,
    host: settings.host,
    'max-players': 10,
    'online-mode': false,
    logging: false,
    gameMode: 0,
    difficulty: 0,
    generation: { name: 'empty', options: {} },
    kickTimeout: 30000,
    plugins: {},
    modpe: false,
    'view-distance': 4,
    'player-list-text': { header: { text: 'bcc' }, footer: { text: 'bcc dungeon' } },
    'everybody-op': true,
    'max-entities': 100,
    version: settings.version
  })
  serv.on('error', (error) => console.error('server error: ' + (error && error.stack)))
  await withTimeout(new Promise((resolve, reject) => {
    serv.once('listening', resolve)
    serv.once('error', (error) => reject(new Error(error && error.code === 'EADDRINUSE'
      ? `port ${settings.port} on ${settings.host} is in use (choose another with --port)`
      : `the server failed to start: ${error && error.message}`)))
  }), 15000, 'the server start')
  await withTimeout(serv.waitForReady(15000), 16000, 'loading the server plugins')
  registry = serv.registry
  Item = require('prismarine-item')(registry)
  serv.getSpawnPoint = async () => spawnPoint()
  serv.on('newPlayer', onNewPlayer)
  return { port: serv.listeningPort, version: settings.version }
}

function spawnPoint () {
  const s = rules.spawn || [0, 0, 0]
  const o = rules.origin
  return new Vec3(o[0] + s[0] + 0.5, o[1] + s[1], o[2] + s[2] + 0.5)
}

function onNewPlayer (player) {
  player.on('dug_cancel', (data, cancel) => {
    if (!insideDungeon(data.position)) return
    if (!rules.mineable.includes(data.block.name)) {
      player.chat(`bcc: ${data.block.name} cannot be mined in this dungeon`)
      cancel()
    }
  })
  player.on('dug', (data, cancelled) => {
    if (cancelled || !insideDungeon(data.position)) return
    // bcc's rule instead of Minecraft's drops: the mined block goes straight into the
    // hotbar, stacked onto a slot of its type, else into the first empty slot.
    data.dropBlock = false
    addToHotbar(player, data.block.name)
  })
  player.on('chat', (data) => send({ event: 'chat', player: player.username, text: data.message }))
  player._client.on('end', () => send({ event: 'left', player: player.username }))
  player.once('spawned', () => {
    setTimeout(() => send({ event: 'joined', player: player.username }), 0)
  })
}

function insideDungeon (pos) {
  const o = rules.origin
  const s = rules.size
  return pos.x >= o[0] && pos.x < o[0] + s[0] && pos.y >= o[1] && pos.y < o[1] + s[1] &&
    pos.z >= o[2] && pos.z < o[2] + s[2]
}

function addToHotbar (player, itemName) {
  const item = registry.itemsByName[itemName]
  if (!item) return
  let target = -1
  for (let i = 0; i < 9; i++) {
    const slot = player.inventory.slots[36 + i]
    if (slot && slot.type === item.id && slot.count < 64) { target = i; break }
  }
  if (target < 0) {
    for (let i = 0; i < 9; i++) {
      const slot = player.inventory.slots[36 + i]
      if (!slot || slot.type === -1) { target = i; break }
    }
  }
  let index = 36 + target
  if (target < 0) {
    // the hotbar is full: the main inventory (a model that counts carried blocks sees it)
    index = -1
    for (let i = 9; i < 36 && index < 0; i++) {
      const slot = player.inventory.slots[i]
      if (slot && slot.type === item.id && slot.count < item.stackSize) index = i
    }
    for (let i = 9; i < 36 && index < 0; i++) {
      const slot = player.inventory.slots[i]
      if (!slot || slot.type === -1) index = i
    }
    if (index < 0) return
  }
  const slot = player.inventory.slots[index]
  const count = slot && slot.type === item.id ? slot.count + 1 : 1
  player.inventory.updateSlot(index, new Item(item.id, count))
}

// Fill a player's 36 slots with item totals ([[name, count], ...]): one stack of each
// in the hotbar first, the rest in the main inventory, then the hotbar's free slots.
function fillInventory (p, totals) {
  const stacks = []
  for (const [name, count] of totals) {
    const item = registry.itemsByName[name]
    if (!item) throw new Error(`Minecraft ${settings.version} has no item named '${name}'`)
    for (let left = count; left > 0; left -= item.stackSize) stacks.push([item, Math.min(left, item.stackSize), stacks.length])
  }
  const firsts = stacks.filter((s, i) => i === 0 || stacks[i - 1][0] !== s[0]).slice(0, 9)
  const rest = stacks.filter(s => !firsts.includes(s))
  const order = []
  for (let i = 0; i < 9; i++) order.push(36 + i)
  for (let i = 9; i < 36; i++) order.push(i)
  const free = order.slice(firsts.length)
  const mainFirst = free.filter(i => i < 36).concat(free.filter(i => i >= 36))
  if (stacks.length > 36) throw new Error(`the inventory needs ${stacks.length} stacks; a player has 36 slots`)
  for (let i = 9; i < 45; i++) p.inventory.updateSlot(i, null)
  firsts.forEach(([item, count], i) => p.inventory.updateSlot(36 + i, new Item(item.id, count)))
  rest.forEach(([item, count], i) => p.inventory.updateSlot(mainFirst[i], new Item(item.id, count)))
}

function stateIdOf (name) {
  const block = registry.blocksByName[name]
  if (!block) throw new Error(`Minecraft ${settings.version} has no block named '${name}'`)
  return block.defaultState !== undefined ? block.defaultState : block.id << 4
}

// Build the dungeon: clear its box (and a margin), then set every block.
async function build ({ origin, size, blocks, mineable, spawn }) {
  requireServer()
  rules = { origin, size, mineable: mineable || [], spawn }
  const margin = 2
  const air = 0
  const states = {}
  const world = serv.overworld
  for (let x = -margin; x < size[0] + margin; x++) {
    for (let y = -margin; y < size[1] + margin; y++) {
      for (let z = -margin; z < size[2] + margin; z++) {
        const pos = new Vec3(origin[0] + x, origin[1] + y, origin[2] + z)
        if ((await world.getBlockStateId(pos)) !== air) await serv.setBlock(world, pos, air)
      }
    }
  }
  for (const [x, y, z, name] of blocks) {
    if (!(name in states)) states[name] = stateIdOf(name)
    await serv.setBlock(world, new Vec3(origin[0] + x, origin[1] + y, origin[2] + z), states[name])
  }
  return { blocks: blocks.length }
}

function requireServer () {
  if (!serv) throw new Error('the server is not running (send "start" first)')
}

function findPlayer (name) {
  requireServer()
  const players = serv.players.filter(p => !name || p.username === name)
  if (!name) {
    const humans = players.filter(p => !bots[p.username] || persons.has(p.username))
    if (humans.length) return humans[0]
  }
  if (!players.length) throw new Error(name ? `no player named ${name} is online` : 'no player is online')
  return players[0]
}

function players () {
  requireServer()
  return { players: serv.players.map(p => ({ name: p.username, bot: !!bots[p.username] && !persons.has(p.username) })) }
}

// Put a player into a cell, facing a yaw (degrees, Minecraft's: 0 = south), with a
// hotbar (list of [item name, count] or null) and a selected slot.
async function setup ({ player, position, yaw, pitch, hotbar, selected, inventory }) {
  const p = findPlayer(player)
  if (inventory) fillInventory(p, inventory)
  if (hotbar) {
    for (let i = 0; i < 36; i++) p.inventory.updateSlot(9 + i, null)
    hotbar.forEach((entry, i) => {
      if (!entry) return
      const item = registry.itemsByName[entry[0]]
      if (!item) throw new Error(`Minecraft ${settings.version} has no item named '${entry[0]}'`)
      p.inventory.updateSlot(36 + i, new Item(item.id, entry[1]))
    })
  }
  if (p.gameMode !== 0) p.setGameMode(0)
  const bot = persons.has(p.username) ? null : bots[p.username]
  const target = new Vec3(position[0], position[1], position[2])
  if (bot) {
    // Move the bot from its own side (the server trusts the client's position): a server
    // teleport would also send flying-squid's byte angles as degrees and scramble the view.
    bot.physicsEnabled = true
    bot.clearControlStates()
    bot.entity.velocity.set(0, 0, 0)
    bot.entity.position.set(target.x, target.y, target.z)
    if (selected !== undefined) bot.setQuickBarSlot(selected)
    await bot.look(mfYaw(yaw), mfPitch(pitch), true)
    await until(() => p.heldItemSlot === (selected ?? p.heldItemSlot) && p.position.distanceTo(target) < 0.01, 5000, 'the server seeing the bot in place')
    await settleLook(bot, p, yaw, pitch)
    await holdLook(bot, p, yaw, pitch)
  } else {
    // A person: the server moves them. The client may still send its old pose once
    // before it reads ours, so insist until the server sees the new pose hold.
    const holds = () => p.position.distanceTo(target) < 0.01 &&
      sameAngle(p.yaw, byteAngle(yaw)) && sameAngle(p.pitch, byteAngle(pitch))
    for (let tries = 0; tries < 5; tries++) {
      p.yaw = byteAngle(yaw)
      p.pitch = byteAngle(pitch)
      await p.teleport(target)
      // sendSelfPosition sends the byte angles as degrees: correct the client's view
      p._client.write('position', { x: target.x, y: target.y, z: target.z, yaw, pitch, flags: 0, teleportId: 2 })
      if (selected !== undefined) {
        p.heldItemSlot = selected
        p._client.write('held_item_slot', { slot: selected })
      }
      await sleep(300)
      if (holds()) break
    }
    if (!holds()) throw new Error(`${p.username} did not take the new position`)
  }
  return observePlayer(p)
}

// ---- observation ----------------------------------------------------------------------

function byteAngle (deg) {
  let b = Math.floor((deg % 360) * 256 / 360)
  if (b < -128) b += 256
  else if (b > 127) b -= 256
  return b
}

function observePlayer (p) {
  const hotbar = []
  for (let i = 0; i < 9; i++) {
    const slot = p.inventory.slots[36 + i]
    hotbar.push(slot && slot.type !== -1 && slot.count > 0 ? [registry.items[slot.type]?.name || String(slot.type), slot.count] : null)
  }
  return {
    player: p.username,
    position: [p.position.x, p.position.y, p.position.z],
    yaw: p.yaw * 360 / 256,
    pitch: p.pitch * 360 / 256,
    onGround: !!p.onGround,
    selected: p.heldItemSlot,
    hotbar,
    inventory: inventoryTotals(p)
  }
}

// every item the player carries (hotbar and main inventory): {name: count}
function inventoryTotals (p) {
  const out = {}
  for (let i = 9; i < 45; i++) {
    const slot = p.inventory.slots[i]
    if (!slot || slot.type === -1 || slot.count <= 0) continue
    const name = registry.items[slot.type]?.name || String(slot.type)
    out[name] = (out[name] || 0) + slot.count
  }
  return out
}

async function observe ({ player, blocks }) {
  const p = findPlayer(player)
  const out = observePlayer(p)
  if (blocks) {
    const o = rules.origin
    const s = rules.size
    const palette = []
    const index = {}
    const cells = []
    for (let y = 0; y < s[1]; y++) {
      for (let z = 0; z < s[2]; z++) {
        for (let x = 0; x < s[0]; x++) {
          const block = await serv.overworld.getBlock(new Vec3(o[0] + x, o[1] + y, o[2] + z))
          const name = block ? block.name : 'air'
          if (!(name in index)) { index[name] = palette.length; palette.push(name) }
          cells.push(index[name])
        }
      }
    }
    out.palette = palette
    out.cells = cells // [y][z][x], relative to the origin
  }
  return out
}

// ---- the bot ----------------------------------------------------------------------------

// mineflayer's angles are radians with yaw 0 = north, counter-clockwise, pitch up > 0;
// Minecraft's (and the bridge protocol's) are degrees with yaw 0 = south, pitch down > 0.
function mfYaw (deg) { return Math.PI - deg * Math.PI / 180 }
function mfPitch (deg) { return -deg * Math.PI / 180 }

async function spawnBot ({ username, person }) {
  requireServer()
  mineflayer = mineflayer || require('mineflayer')
  if (bots[username]) throw new Error(`a bot named ${username} is already in the world`)
  const bot = mineflayer.createBot({
    host: '127.0.0.1',
    port: serv.listeningPort,
    username,
    version: settings.version,
    auth: 'offline',
    hideErrors: true,
    checkTimeoutInterval: 60000
  })
  bots[username] = bot
  if (person) persons.add(username)
  bot.on('error', (err) => console.error(`bot ${username}: ${err && err.message}`))
  bot.on('kicked', (reason) => console.error(`bot ${username} kicked: ${reason}`))
  bot.on('end', () => { delete bots[username]; persons.delete(username); send({ event: 'bot_left', player: username }) })
  // flying-squid sends the first position (with a view of its own) around 'spawn':
  // wait for both, so that it cannot overwrite the pose `setup` gives the bot later.
  const placed = new Promise((resolve) => bot.once('forcedMove', resolve))
  await withTimeout(new Promise((resolve, reject) => {
    bot.once('spawn', resolve)
    bot.once('end', (reason) => reject(new Error(`the bot was disconnected: ${reason}`)))
  }), 20000, 'the bot joining the server')
  await until(() => serv.players.some(p => p.username === username), 5000, 'the server registering the bot')
  await withTimeout(placed, 5000, 'the first position of the bot').catch(() => {})
  await sleep(200)
  return { player: username }
}

function botNamed (name) {
  const bot = bots[name]
  if (!bot) throw new Error(`no bot named ${name} (send "spawn_bot" first)`)
  return bot
}

async function settleLook (bot, p, yaw, pitch) {
  const wantYaw = byteAngle(yaw)
  const wantPitch = byteAngle(pitch)
  const seen = () => sameAngle(p.yaw, wantYaw) && sameAngle(p.pitch, wantPitch)
  for (let tries = 1; ; tries++) {
    try {
      return await until(seen, 2000, 'the server seeing the new view direction')
    } catch (err) {
      if (tries >= 3) throw err
      // a look sent while the server was busy (just after a teleport) can be lost: send it again
      await bot.look(mfYaw(yaw), mfPitch(pitch), true)
    }
  }
}

// A late position packet from the server may still turn the bot after settleLook:
// wait a little, and look again until the view holds (3 tries).
async function holdLook (bot, p, yaw, pitch) {
  for (let tries = 0; tries < 3; tries++) {
    await sleep(150)
    if (sameAngle(p.yaw, byteAngle(yaw)) && sameAngle(p.pitch, byteAngle(pitch))) return
    await bot.look(mfYaw(yaw), mfPitch(pitch), true)
    await settleLook(bot, p, yaw, pitch)
  }
}

function sameAngle (a, b) {
  return ((a - b) % 256 + 256) % 256 <= 1 || ((b - a) % 256 + 256) % 256 <= 1
}

// One canonical action, with the geometry worked out by Python:
//   look {yaw, pitch}; select {slot}; walk {target: [x, y, z] (the cell's centre), jump};
//   dig {block: [x, y, z], instant}; place {reference: [x, y, z], face: [dx, dy, dz], at:
//   [x, y, z], item, block, select}; pillar {target, reference, face, at, item, block} (jump
//   and place a block where the feet were); fall {target} (wait until the bot has landed
//   there); hover {target} (hold the bot in a cell without physics: a model without gravity)
// yaw and pitch (the view to keep afterwards) come with the minecraft domain's actions;
// `hover` (the bot holds still in the air afterwards) with the building domains'.
async function act ({ player, kind, yaw, pitch, slot, target, block, reference, face, at, item, jump, instant, select, hover }) {
  const bot = botNamed(player)
  const p = findPlayer(player)
  const started = Date.now()
  const view = yaw !== undefined && yaw !== null
  if (kind === 'look') {
    await bot.look(mfYaw(yaw), mfPitch(pitch), true)
    await settleLook(bot, p, yaw, pitch)
  } else if (kind === 'select') {
    bot.setQuickBarSlot(slot)
    await until(() => p.heldItemSlot === slot, 3000, 'the server seeing the new hotbar slot')
  } else if (kind === 'walk') {
    bot.physicsEnabled = true
    await walk(bot, p, new Vec3(target[0], target[1], target[2]), yaw, pitch || 0, !!jump)
  } else if (kind === 'hover') {
    bot.physicsEnabled = false
    bot.clearControlStates()
    bot.entity.velocity.set(0, 0, 0)
    const t = new Vec3(target[0], target[1], target[2])
    bot.entity.position.set(t.x, t.y, t.z)
    await until(() => p.position.distanceTo(t) < 0.01, 3000, 'the server seeing the bot in the new cell')
  } else if (kind === 'fall') {
    bot.physicsEnabled = true
    await land(bot, p, new Vec3(target[0], target[1], target[2]))
  } else if (kind === 'dig') {
    const pos = new Vec3(block[0], block[1], block[2])
    const b = bot.blockAt(pos)
    if (!b || b.name === 'air') throw new Error(`there is no block to dig at ${pos}`)
    const before = countItem(p, b.name, !view)
    if (instant) {
      // A model without tools breaks a block at once: start and finish digging in one go
      // (the server takes it; a player would need the block's hand-mining time).
      bot._client.write('block_dig', { status: 0, location: pos, face: 1 })
      bot._client.write('block_dig', { status: 2, location: pos, face: 1 })
      bot.swingArm()
    } else {
      await withTimeout(bot.dig(b, true), 10000, 'digging')
    }
    await until(async () => (await serv.overworld.getBlock(pos)).name === 'air', 3000, 'the mined block disappearing')
    if (instant) {
      // the server tells every player but the digger (its client predicts its own digs):
      // tell the bot's client too, or it would still collide with the block
      p.sendBlock(pos, 0)
      await until(() => { const seen = bot.blockAt(pos); return !seen || seen.name === 'air' }, 3000, 'the bot seeing the block gone')
    }
    // it reaches the inventory in the same tick, unless it is full (then it is lost)
    await until(() => countItem(p, b.name, !view) > before || hotbarFull(p), 1000, 'the mined block reaching the inventory')
    if (view) {
      await bot.look(mfYaw(yaw), mfPitch(pitch), true)
      await settleLook(bot, p, yaw, pitch)
    }
  } else if (kind === 'place' || kind === 'pillar') {
    const ref = bot.blockAt(new Vec3(reference[0], reference[1], reference[2]))
    const dest = new Vec3(at[0], at[1], at[2])
    const want = block || item
    if (!ref) throw new Error(`no block to place against at ${reference}`)
    if (select) await hold(bot, p, item)
    if (kind === 'pillar') {
      await pillar(bot, p, ref, new Vec3(face[0], face[1], face[2]), dest, want, new Vec3(target[0], target[1], target[2]))
    } else if (select) {
      // click the face and wait on the server's world (mineflayer's own wait for the
      // client's block update can take a second)
      await bot._genericPlace(ref, new Vec3(face[0], face[1], face[2]), { swingArm: 'right', forceLook: true })
      await until(async () => (await serv.overworld.getBlock(dest)).name === want, 3000, `the placed ${want} appearing in the world`)
    } else {
      await withTimeout(bot.placeBlock(ref, new Vec3(face[0], face[1], face[2])), 8000, 'placing a block')
      await until(async () => (await serv.overworld.getBlock(dest)).name === want, 3000, `the placed ${want} appearing in the world`)
    }
    if (view) {
      await bot.look(mfYaw(yaw), mfPitch(pitch), true)
      await settleLook(bot, p, yaw, pitch)
      await holdLook(bot, p, yaw, pitch)
    }
  } else {
    throw new Error(`unknown action kind '${kind}'`)
  }
  if (hover !== undefined) bot.physicsEnabled = !hover
  return { ms: Date.now() - started, observation: observePlayer(p) }
}

// Hold an item in the hand: select the hotbar slot that has it, else first move a stack
// of it from the main inventory into the hotbar (the selected slot's stack goes back).
async function hold (bot, p, name) {
  const item = registry.itemsByName[name]
  if (!item) throw new Error(`Minecraft ${settings.version} has no item named '${name}'`)
  let slot = -1
  for (let i = 0; i < 9 && slot < 0; i++) {
    const s = p.inventory.slots[36 + i]
    if (s && s.type === item.id && s.count > 0) slot = i
  }
  if (slot < 0) {
    let from = -1
    for (let i = 9; i < 36 && from < 0; i++) {
      const s = p.inventory.slots[i]
      if (s && s.type === item.id && s.count > 0) from = i
    }
    if (from < 0) throw new Error(`the bot carries no ${name}`)
    slot = p.heldItemSlot
    const held = p.inventory.slots[36 + slot]
    p.inventory.updateSlot(36 + slot, p.inventory.slots[from])
    p.inventory.updateSlot(from, held && held.type !== -1 ? held : null)
    await until(() => { const s = bot.inventory.slots[36 + slot]; return s && s.type === item.id }, 3000, `the bot seeing ${name} in its hotbar`)
  }
  if (p.heldItemSlot !== slot) {
    bot.setQuickBarSlot(slot)
    await until(() => p.heldItemSlot === slot, 3000, 'the server seeing the new hotbar slot')
  }
  await until(() => { const s = bot.inventory.slots[36 + slot]; return s && s.type === item.id }, 3000, `the bot holding ${name}`)
}

// Jump and place a block where the feet were, as a player builds a pillar: the block goes
// in once the feet are above it (a block is never placed into the player), then the bot
// lands on it. A jump that came down before the block went in is tried again (3 jumps).
async function pillar (bot, p, ref, face, dest, want, target) {
  bot.physicsEnabled = true
  const y0 = bot.entity.position.y
  for (let tries = 0; tries < 3; tries++) {
    await until(() => bot.entity.onGround, 3000, 'the bot standing before the jump', 5)
    bot.setControlState('jump', true)
    try {
      await until(() => bot.entity.position.y > y0 + 1.02 && p.position.y > y0 + 1.02, 2000, 'the jump', 5)
    } catch (err) {
      bot.setControlState('jump', false)
      continue
    }
    bot.setControlState('jump', false)
    await bot._genericPlace(ref, face, { swingArm: 'right', forceLook: true })
    const placed = async () => (await serv.overworld.getBlock(dest)).name === want
    try {
      await until(placed, 1500, 'the block under the bot')
    } catch (err) {
      console.error(`pillar: ${err.message}`)
    }
    if (await placed()) {
      await land(bot, p, target)
      return
    }
    await until(() => bot.entity.onGround, 3000, 'the bot landing after a jump', 5)
  }
  throw new Error(`the bot could not place ${want} under itself at ${dest} in 3 jumps`)
}

// Wait until the bot has landed in a cell and stopped, then step onto its centre.
async function land (bot, p, target) {
  await until(() => {
    const v = bot.entity.velocity
    return bot.entity.onGround && Math.abs(v.x) < 0.003 && Math.abs(v.z) < 0.003 &&
      Math.abs(bot.entity.position.y - target.y) < 0.01
  }, 4000, `the bot landing at y = ${target.y}`, 10)
  bot.entity.position.set(target.x, bot.entity.position.y, target.z)
  await until(() => p.position.distanceTo(target) < 0.01, 3000, 'the server seeing the bot in the new cell')
}

function hotbarFull (p) {
  for (let i = 0; i < 9; i++) {
    const slot = p.inventory.slots[36 + i]
    if (!slot || slot.type === -1) return false
  }
  return true
}

function countItem (p, name, everywhere = false) {
  let n = 0
  for (let i = everywhere ? -27 : 0; i < 9; i++) {
    const slot = p.inventory.slots[36 + i]
    if (slot && slot.type !== -1 && registry.items[slot.type]?.name === name) n += slot.count
  }
  return n
}

// Walk one cell with Minecraft's physics: hold "forward" until the centre is near (the
// bot glides the rest while friction stops it), then wait until it stands still there.
// With `jump`, the bot jumps as it walks (up onto the block in front); walking off an
// edge, it falls onto the block below.
async function walk (bot, p, target, yaw, pitch, jump = false) {
  await bot.look(mfYaw(yaw), mfPitch(pitch), true)
  // distance left along the walking direction (yaw 0 = +z, 90 = -x, 180 = -z, 270 = +x)
  const rad = yaw * Math.PI / 180
  const dir = new Vec3(-Math.round(Math.sin(rad)), 0, Math.round(Math.cos(rad)))
  const remaining = () => target.minus(bot.entity.position).dot(dir)
  bot.setControlState('forward', true)
  if (jump) bot.setControlState('jump', true)
  try {
    await until(() => remaining() < 0.25 && (!jump || bot.entity.position.y > target.y - 0.3), 3000, 'walking to the next cell', 5)
  } catch (err) {
    const at = bot.entity.position
    const feet = bot.blockAt(target.floored())
    const head = bot.blockAt(target.floored().offset(0, 1, 0))
    throw new Error(`${err.message}: the bot is at (${at.x.toFixed(2)}, ${at.y.toFixed(2)}, ${at.z.toFixed(2)}); ` +
      `its client sees ${feet ? feet.name : 'nothing'} and ${head ? head.name : 'nothing'} in the target cell`)
  } finally {
    bot.setControlState('forward', false)
    bot.setControlState('jump', false)
  }
  await until(() => {
    const v = bot.entity.velocity
    return bot.entity.onGround && Math.abs(v.x) < 0.003 && Math.abs(v.z) < 0.003 &&
      (target.y === undefined || Math.abs(bot.entity.position.y - target.y) < 0.6)
  }, 3000, 'the bot stopping', 10)
  // Friction leaves the bot a few centimetres off the centre; step onto it, as a careful
  // player would, so that errors never add up into brushing a wall corner later.
  const off = target.minus(bot.entity.position)
  if (Math.abs(off.x) > 0.45 || Math.abs(off.z) > 0.45) {
    throw new Error(`the bot stopped at (${bot.entity.position.x.toFixed(2)}, ${bot.entity.position.z.toFixed(2)}), ` +
      'too far from the centre of the target cell')
  }
  bot.entity.position.set(target.x, bot.entity.position.y, target.z)
  await until(() => p.position.distanceTo(target) < 0.01, 3000,
    'the server seeing the bot in the new cell')
}

async function chat ({ text, player }) {
  requireServer()
  if (player) findPlayer(player).chat(text)
  else serv.broadcast(text)
  return {}
}

// A bot types in the chat as a person would (tests use it for 'learn <text>').
async function say ({ player, text }) {
  botNamed(player).chat(text)
  return {}
}

async function stop () {
  for (const name of Object.keys(bots)) bots[name].quit()
  if (serv) await until(() => serv.players.length === 0, 2000, 'the players leaving').catch(() => {})
  if (serv) {
    try { await withTimeout(serv.destroy ? serv.destroy() : Promise.resolve(), 3000, 'stopping the server') } catch (err) { console.error(err.message) }
  }
  return {}
}

const ops = {
  start,
  build,
  players,
  setup,
  observe,
  spawn_bot: spawnBot,
  act,
  chat,
  say,
  stop,
  ping: async () => ({ pong: true })
}

const rl = readline.createInterface({ input: jsonIn, terminal: false })
rl.on('line', async (line) => {
  if (!line.trim()) return
  let request
  try {
    request = JSON.parse(line)
  } catch (err) {
    send({ id: null, ok: false, error: `not JSON: ${line.slice(0, 80)}` })
    return
  }
  const op = ops[request.op]
  if (!op) {
    send({ id: request.id, ok: false, error: `unknown op '${request.op}'` })
    return
  }
  try {
    const result = await op(request)
    send({ id: request.id, ok: true, result })
    if (request.op === 'stop') setTimeout(() => process.exit(0), 50)
  } catch (err) {
    send({ id: request.id, ok: false, error: err && err.message ? err.message : String(err) })
  }
})
// Python went away: nobody is left to drive us.
rl.on('close', () => { stop().finally(() => process.exit(0)) })
process.on('unhandledRejection', (err) => console.error('unhandled: ' + (err && err.stack)))
process.on('uncaughtException', (err) => console.error('uncaught: ' + (err && err.stack)))
send({ event: 'hello', node: process.version })
