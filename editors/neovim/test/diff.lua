-- :RapidDiff in headless Neovim (called by e2e.lua): a backup of the
-- workspace made before two changes (a target moved by 12.5 mm, a statement
-- added) against the workspace: the command opens a Markdown buffer that
-- holds what `rapid diff BACKUP WORKSPACE --format markdown` says.
return function(ctx)
  local check, expect, run, ws, rapid_bin = ctx.check, ctx.expect, ctx.run, ctx.ws, ctx.rapid_bin

  check(':RapidDiff BACKUP opens the Markdown report of the changes since the backup', function()
    local backup = vim.fn.tempname() .. '/backup-before'
    vim.fn.mkdir(backup, 'p')
    for _, name in ipairs(vim.fn.readdir(ws)) do
      local text = table.concat(vim.fn.readfile(ws .. '/' .. name, 'b'), '\n')
      if name == 'MainModule.mod' then
        local before = text:gsub('%[%[812%.5,%-402%.1,455%]', '[[800,-402.1,455]', 1)
        before = before:gsub('\n        nPlaced := "none";', '', 1)
        expect(before ~= text, 'the workspace changed: the backup edits do not apply')
        text = before
      end
      vim.fn.writefile(vim.split(text, '\n'), backup .. '/' .. name, 'b')
    end
    local want, code, err = run({ rapid_bin, 'diff', backup, ws, '--format', 'markdown' })
    expect(code == 0, 'rapid diff: %s', err)
    expect(want:find('`pPickAbove` | 12.5 mm', 1, true), 'rapid diff --format markdown: %s', want)
    -- From a buffer of the workspace: the backup alone is compared with its project.
    vim.cmd('tabnew ' .. vim.fn.fnameescape(ws .. '/MainModule.mod'))
    local from = vim.api.nvim_get_current_buf()
    vim.cmd('RapidDiff ' .. vim.fn.fnameescape(backup))
    local b = vim.api.nvim_get_current_buf()
    expect(b ~= from, 'no new buffer')
    expect(vim.bo[b].filetype == 'markdown', 'the report\'s filetype is %s', vim.bo[b].filetype)
    local shown = table.concat(vim.api.nvim_buf_get_lines(b, 0, -1, false), '\n')
    local text = vim.trim(want)
    -- the sides are named as given: the rest is the same report
    shown = shown:gsub('^[^\n]*\n', '')
    text = text:gsub('^[^\n]*\n', '')
    expect(shown == text, 'the buffer shows:\n%s\nrapid diff says:\n%s', shown, text)
    vim.cmd('tabclose')
    vim.cmd('tabclose')
    -- A side that is not there: a message, no buffer.
    local before = #vim.api.nvim_list_bufs()
    vim.cmd('RapidDiff ' .. vim.fn.fnameescape(backup .. '/nowhere') .. ' ' .. vim.fn.fnameescape(ws))
    expect(#vim.api.nvim_list_bufs() == before, 'a buffer for a failed diff')
  end)
end
